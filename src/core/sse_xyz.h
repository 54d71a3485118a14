#pragma once
// A 3-vector in a 128-bit register: x, y and z in lanes 0-2, lane 3 cleared. Loads of a vec3
// bring in whatever follows it (an index, a material), whose bits may be a subnormal float;
// arithmetic on one can take a microcode assist costing a hundred cycles or more.

#include <emmintrin.h>

namespace raylab {

// v with lane 3 zero, lanes 0-2 unchanged bit for bit.
inline __m128 xyzOf(__m128 v) {
    return _mm_and_ps(v, _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)));
}

} // namespace raylab
