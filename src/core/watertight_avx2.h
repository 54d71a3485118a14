#pragma once
// The arithmetic of the watertight triangle test (triangle_intersection.cpp) on 8 lanes, shared
// by the two AVX2 traversals: 8 triangles against one ray (bvh_traverse_avx2.cpp) and one
// triangle against 8 rays (bvh_packet_avx2.cpp). Only files that run on CPUs with AVX2 may call
// it (buildBvh builds the 8-wide form only there).
//
// From the sheared vertices on, it performs intersectTriangle's operations in the same order,
// each rounded the same way (IEEE single precision, no fused multiply-add: core builds with
// -ffp-contract=off), so t, u and v are bit for bit those of the scalar test. Lanes where an edge
// function is exactly zero, where the scalar test switches to double precision, are reported in
// `exact` for the caller to test with intersectTriangle itself.

#include "ray.h"

#include <immintrin.h>

// Functions that use AVX2 (and POPCNT, which every AVX2 CPU has) in a baseline x86-64 build.
#define RAYLAB_AVX2 __attribute__((target("avx2,popcnt")))

namespace raylab {

struct LaneHits {
    unsigned hits;         // lanes hit with tMin < t < tMax (never an `exact` lane)
    unsigned exact;        // lanes with an edge function of exactly zero
    __m256 t, e1, e2, det; // for hit lanes: u = e1 / det, v = e2 / det
};

// x[i], y[i]: vertex i (a, b, c) relative to the ray origin and sheared, as intersectTriangle's
// ax = a[kx] - shearX * a[kz] and ay = a[ky] - shearY * a[kz]; z[i]: a[kz] before the shearZ
// scale. shearZ, tMin and tMax are the rays' (one per lane, or one broadcast).
RAYLAB_AVX2 inline LaneHits watertightLanes(const __m256 x[3], const __m256 y[3], const __m256 z[3],
                                            __m256 shearZ, __m256 tMin, __m256 tMax) {
    // e0 = cx*by - cy*bx; e1 = ax*cy - ay*cx; e2 = bx*ay - by*ax
    const __m256 e0 = _mm256_sub_ps(_mm256_mul_ps(x[2], y[1]), _mm256_mul_ps(y[2], x[1]));
    const __m256 e1 = _mm256_sub_ps(_mm256_mul_ps(x[0], y[2]), _mm256_mul_ps(y[0], x[2]));
    const __m256 e2 = _mm256_sub_ps(_mm256_mul_ps(x[1], y[0]), _mm256_mul_ps(y[1], x[0]));

    const __m256 zero = _mm256_setzero_ps();
    const __m256 anyZero = _mm256_or_ps(
        _mm256_or_ps(_mm256_cmp_ps(e0, zero, _CMP_EQ_OQ), _mm256_cmp_ps(e1, zero, _CMP_EQ_OQ)),
        _mm256_cmp_ps(e2, zero, _CMP_EQ_OQ));
    // With no edge function zero, the scalar test's "some < 0 and some > 0" is "the signs
    // differ". (A NaN lane may pass here; its det is NaN and fails below, as in the scalar test.)
    const __m256 signsDiffer = _mm256_or_ps(_mm256_xor_ps(e0, e1), _mm256_xor_ps(e0, e2));
    const unsigned exact = static_cast<unsigned>(_mm256_movemask_ps(anyZero));
    const unsigned inside =
        ~(static_cast<unsigned>(_mm256_movemask_ps(signsDiffer)) | exact) & 0xffu;
    if (inside == 0) { // the common case: every lane misses
        return {0, exact, zero, zero, zero, zero};
    }
    const __m256 det = _mm256_add_ps(_mm256_add_ps(e0, e1), e2);
    const __m256 absDet = _mm256_andnot_ps(_mm256_set1_ps(-0.0f), det);
    // det != 0 and finite: 0 < |det| < inf (false for NaN).
    const __m256 detOk =
        _mm256_and_ps(_mm256_cmp_ps(absDet, zero, _CMP_GT_OQ),
                      _mm256_cmp_ps(absDet, _mm256_set1_ps(kInfinity), _CMP_LT_OQ));
    const __m256 tScaled =
        _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(e0, _mm256_mul_ps(shearZ, z[0])),
                                    _mm256_mul_ps(e1, _mm256_mul_ps(shearZ, z[1]))),
                      _mm256_mul_ps(e2, _mm256_mul_ps(shearZ, z[2])));
    const __m256 t = _mm256_div_ps(tScaled, det);
    const __m256 inRange =
        _mm256_and_ps(_mm256_cmp_ps(t, tMin, _CMP_GT_OQ), _mm256_cmp_ps(t, tMax, _CMP_LT_OQ));
    const unsigned hits =
        inside & static_cast<unsigned>(_mm256_movemask_ps(_mm256_and_ps(detOk, inRange)));
    return {hits, exact, t, e1, e2, det};
}

} // namespace raylab
