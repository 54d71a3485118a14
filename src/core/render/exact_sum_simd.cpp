#include "render/exact_sum_simd.h"

#include "avx512_warnings.h" // first: before any intrinsics header

#include <cstdint>
#include <cstring>

#if defined(__x86_64__) || defined(_M_X64)
#include <immintrin.h>
#define RAYLAB_HAVE_X86 1
#endif

namespace raylab {

static_assert(sizeof(PixelSum) == 48, "a PixelSum is three 128-bit sums, each low word first");

void addSamples8Scalar(PixelSum* sums, const float* r, const float* g, const float* b) {
    for (int k = 0; k < 8; ++k) {
        sums[k].add(glm::vec3(r[k], g[k], b[k]));
    }
}

bool avx512Supported() {
#ifdef RAYLAB_HAVE_X86
    static const bool supported =
        __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
    return supported;
#else
    return false;
#endif
}

#ifdef RAYLAB_HAVE_X86

namespace {

#define RAYLAB_AVX512 __attribute__((target("avx512f,avx512dq")))

// Permute indices. kValueIndex[j]: the float bits of values 8j .. 8j + 7 of the sequence r[0],
// g[0], b[0], r[1], ... as 64-bit lanes, taken from the registers rg (r, then g) and bAndZeros
// (b, then zeros). kWordIndex[h]: the low and high words of values 4h .. 4h + 3 of a group of
// eight, interleaved as the sums hold them.
struct PermuteTables {
    alignas(64) int32_t value[3][16];
    alignas(64) int64_t word[2][8];
};

constexpr PermuteTables makePermuteTables() {
    PermuteTables t{};
    for (int j = 0; j < 3; ++j) {
        for (int lane = 0; lane < 8; ++lane) {
            const int value = 8 * j + lane;
            const int pixel = value / 3;
            const int channel = value % 3;
            t.value[j][2 * lane] = channel == 0 ? pixel : (channel == 1 ? 8 + pixel : 16 + pixel);
            t.value[j][2 * lane + 1] = 24; // a zero of bAndZeros
        }
    }
    for (int h = 0; h < 2; ++h) {
        for (int q = 0; q < 4; ++q) {
            t.word[h][2 * q] = 4 * h + q;         // the low word, from the first source
            t.word[h][2 * q + 1] = 8 + 4 * h + q; // the high word, from the second
        }
    }
    return t;
}

constexpr PermuteTables kPermute = makePermuteTables();

// toFixed of eight floats (their bits in 64-bit lanes) as eight 128-bit values, low and high
// words apart; `exact` gets the lanes whose float is in toFixed's exact range or 0.
RAYLAB_AVX512 inline void fixedOf(__m512i bits, __m512i& low, __m512i& high, __mmask8& exact) {
    const __m512i biased = _mm512_and_si512(_mm512_srli_epi64(bits, 23), _mm512_set1_epi64(0xff));
    const __m512i magnitudeBits = _mm512_and_si512(bits, _mm512_set1_epi64(0x7fffffff));
    const __mmask8 nonZero = _mm512_test_epi64_mask(magnitudeBits, magnitudeBits);
    // 2^-40 has biased exponent 87, 2^31 has 158.
    const __mmask8 inRange = _mm512_cmple_epu64_mask(
        _mm512_sub_epi64(biased, _mm512_set1_epi64(87)), _mm512_set1_epi64(157 - 87));
    exact = static_cast<__mmask8>(~nonZero) | inRange;
    // x * 2^64 = significand << (biased - 86); variable shifts of 64 or more give 0, and a
    // "negative" count is a huge unsigned one.
    const __m512i significand = _mm512_or_si512(_mm512_and_si512(bits, _mm512_set1_epi64(0x7fffff)),
                                                _mm512_set1_epi64(0x800000));
    const __m512i shift = _mm512_sub_epi64(biased, _mm512_set1_epi64(86));
    low = _mm512_maskz_sllv_epi64(nonZero, significand, shift);
    high = _mm512_maskz_or_epi64(
        nonZero, _mm512_srlv_epi64(significand, _mm512_sub_epi64(_mm512_set1_epi64(64), shift)),
        _mm512_sllv_epi64(significand, _mm512_sub_epi64(shift, _mm512_set1_epi64(64))));
    // Negative floats: the 128-bit two's complement, -low and ~high plus the carry of -low (1
    // when low is 0).
    const __mmask8 negative = _mm512_test_epi64_mask(bits, _mm512_set1_epi64(0x80000000));
    const __mmask8 lowIsZero = _mm512_cmpeq_epi64_mask(low, _mm512_setzero_si512());
    const __m512i invertedHigh = _mm512_xor_si512(high, _mm512_set1_epi64(-1));
    high = _mm512_mask_blend_epi64(
        negative, high,
        _mm512_mask_add_epi64(invertedHigh, lowIsZero, invertedHigh, _mm512_set1_epi64(1)));
    low = _mm512_mask_sub_epi64(low, negative, _mm512_setzero_si512(), low);
}

constexpr __mmask8 kLowWords = 0x55;

RAYLAB_AVX512 bool addSamples8Avx512Kernel(PixelSum* sums, const float* r, const float* g,
                                           const float* b) {
    const __m512i rg = _mm512_inserti64x4(
        _mm512_castsi256_si512(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(r))),
        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(g)), 1);
    const __m512i bAndZeros =
        _mm512_zextsi256_si512(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(b)));
    __m512i low[3], high[3];
    __mmask8 exact = 0xff;
    for (int j = 0; j < 3; ++j) {
        const __m512i bits =
            _mm512_permutex2var_epi32(rg, _mm512_load_si512(kPermute.value[j]), bAndZeros);
        __mmask8 lanes = 0;
        fixedOf(bits, low[j], high[j], lanes);
        exact &= lanes;
    }
    if (exact != 0xff) {
        return false;
    }
    // The 8 sums are 48 64-bit words, pixel by pixel, channel by channel, low word first.
    auto* words = reinterpret_cast<uint64_t*>(sums);
    const __m512i ones = _mm512_set1_epi64(1);
    for (int v = 0; v < 6; ++v) {
        const __m512i value = _mm512_permutex2var_epi64(
            low[v / 2], _mm512_load_si512(kPermute.word[v % 2]), high[v / 2]);
        const __m512i held = _mm512_loadu_si512(words + 8 * v);
        __m512i sum = _mm512_add_epi64(held, value);
        const __mmask8 carry = _mm512_cmplt_epu64_mask(sum, value) & kLowWords;
        sum = _mm512_mask_add_epi64(sum, static_cast<__mmask8>(carry << 1), sum, ones);
        _mm512_storeu_si512(words + 8 * v, sum);
    }
    return true;
}

} // namespace

bool addSamples8Avx512(PixelSum* sums, const float* r, const float* g, const float* b) {
    return avx512Supported() && addSamples8Avx512Kernel(sums, r, g, b);
}

#else

bool addSamples8Avx512(PixelSum*, const float*, const float*, const float*) { return false; }

#endif

void addSamples8(PixelSum* sums, const float* r, const float* g, const float* b) {
    if (!addSamples8Avx512(sums, r, g, b)) {
        addSamples8Scalar(sums, r, g, b);
    }
}

} // namespace raylab
