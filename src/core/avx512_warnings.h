#pragma once
// Included first by the files that use AVX-512 intrinsics. GCC 12's AVX-512 intrinsics start from
// _mm512_undefined_*() values, which its -Wuninitialized reports in the intrinsics' own headers;
// the pragmas must come before the first include of those headers, and hold for the rest of the
// file. (Clang does not warn there.)

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
