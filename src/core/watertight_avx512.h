#pragma once
// The arithmetic of the watertight triangle test (triangle_intersection.cpp) on 16 lanes with
// AVX-512F: one triangle against 16 rays (bvh_packet16_avx512.cpp). Only files that run on CPUs
// with AVX-512F may call it.
//
// The operations are watertightLanes' (watertight_avx2.h) in the same order, each rounded the same
// way (no fused multiply-add: core builds with -ffp-contract=off), so t, u and v are bit for bit
// those of the scalar test; lanes with an edge function of exactly zero are reported in `exact`.

#include "ray.h"

#include <immintrin.h>

// Functions that use AVX-512F on top of AVX2 in a baseline x86-64 build.
#define RAYLAB_AVX512 __attribute__((target("avx2,popcnt,avx512f")))

namespace raylab {

struct LaneHits16 {
    unsigned hits;         // lanes hit with tMin < t < tMax (never an `exact` lane)
    unsigned exact;        // lanes with an edge function of exactly zero
    __m512 t, e1, e2, det; // for hit lanes: u = e1 / det, v = e2 / det
};

// The lanes whose sign bit is set (AVX-512F has no movemask for floats).
RAYLAB_AVX512 inline unsigned signBits16(__m512 x) {
    return _mm512_cmplt_epi32_mask(_mm512_castps_si512(x), _mm512_setzero_si512());
}

// As watertightLanes: x[i], y[i] are vertex i (a, b, c) relative to the ray origin and sheared,
// z[i] its kz coordinate before the shearZ scale.
RAYLAB_AVX512 inline LaneHits16 watertightLanes16(const __m512 x[3], const __m512 y[3],
                                                  const __m512 z[3], __m512 shearZ, __m512 tMin,
                                                  __m512 tMax) {
    // e0 = cx*by - cy*bx; e1 = ax*cy - ay*cx; e2 = bx*ay - by*ax
    const __m512 e0 = _mm512_sub_ps(_mm512_mul_ps(x[2], y[1]), _mm512_mul_ps(y[2], x[1]));
    const __m512 e1 = _mm512_sub_ps(_mm512_mul_ps(x[0], y[2]), _mm512_mul_ps(y[0], x[2]));
    const __m512 e2 = _mm512_sub_ps(_mm512_mul_ps(x[1], y[0]), _mm512_mul_ps(y[1], x[0]));

    const __m512 zero = _mm512_setzero_ps();
    const unsigned exact = _mm512_cmp_ps_mask(e0, zero, _CMP_EQ_OQ) |
                           _mm512_cmp_ps_mask(e1, zero, _CMP_EQ_OQ) |
                           _mm512_cmp_ps_mask(e2, zero, _CMP_EQ_OQ);
    // With no edge function zero, "some < 0 and some > 0" is "the signs differ".
    const __m512i b0 = _mm512_castps_si512(e0);
    const unsigned signsDiffer = signBits16(
        _mm512_castsi512_ps(_mm512_or_si512(_mm512_xor_si512(b0, _mm512_castps_si512(e1)),
                                            _mm512_xor_si512(b0, _mm512_castps_si512(e2)))));
    const unsigned inside = ~(signsDiffer | exact) & 0xffffu;
    if (inside == 0) { // the common case: every lane misses
        return {0, exact, zero, zero, zero, zero};
    }
    const __m512 det = _mm512_add_ps(_mm512_add_ps(e0, e1), e2);
    const __m512 absDet = _mm512_abs_ps(det);
    // det != 0 and finite: 0 < |det| < inf (false for NaN).
    const unsigned detOk = _mm512_cmp_ps_mask(absDet, zero, _CMP_GT_OQ) &
                           _mm512_cmp_ps_mask(absDet, _mm512_set1_ps(kInfinity), _CMP_LT_OQ);
    const __m512 tScaled =
        _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(e0, _mm512_mul_ps(shearZ, z[0])),
                                    _mm512_mul_ps(e1, _mm512_mul_ps(shearZ, z[1]))),
                      _mm512_mul_ps(e2, _mm512_mul_ps(shearZ, z[2])));
    const __m512 t = _mm512_div_ps(tScaled, det);
    const unsigned inRange =
        _mm512_cmp_ps_mask(t, tMin, _CMP_GT_OQ) & _mm512_cmp_ps_mask(t, tMax, _CMP_LT_OQ);
    return {inside & detOk & inRange, exact, t, e1, e2, det};
}

} // namespace raylab
