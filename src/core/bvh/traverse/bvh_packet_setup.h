#pragma once
// Per-lane constants of a packet of up to 8 rays (internal to bvh_packet_avx2.cpp, which is the
// only file that may include this: it uses AVX2 and must only run on CPUs that have it).
//
// Each field of the 8 rays (RayPacket, structure of arrays) is one register. The lanes that
// trace together are the valid ones (WatertightRay's test) sharing the
// most common ray permutation; the other lanes keep whatever they hold and are never read back.

#include "bvh/bvh_wide.h"
#include "bvh/traverse/bvh_box_ray.h"
#include "ray_packet.h"
#include "watertight_avx2.h"

#include <immintrin.h>

namespace raylab {

struct PacketRays {
    unsigned lanes = 0;           // lanes traced as a packet
    unsigned others = 0;          // valid lanes with another permutation (single-ray path)
    int k[3] = {0, 1, 2};         // the packet's permutation kx, ky, kz
    __m256 origin[3], inverse[3]; // box test: world axes, 1 / boxDirection(d)
    __m256 tMin, tMax;
    __m256 originK[3]; // triangle test: origin in the order kx, ky, kz
    __m256 shearX, shearY, shearZ;
    int vertexOffset[3]; // k[i] * 8: where axis k[i] starts in a BvhTriangleBlock vertex
};

// Lanes whose value is finite (not NaN, not +-inf).
RAYLAB_AVX2 inline __m256 isFinite8(__m256 x) {
    return _mm256_cmp_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), x), _mm256_set1_ps(kInfinity),
                         _CMP_LT_OQ);
}

// WatertightRay's permutation for the axis kz of a ray's largest |d| and the sign of d[kz]: kx
// and ky follow kz cyclically and swap when d[kz] < 0.
inline void rayPermutation(int kz, bool negative, int k[3]) {
    const int next = kz == 2 ? 0 : kz + 1;
    const int after = next == 2 ? 0 : next + 1;
    k[0] = negative ? after : next;
    k[1] = negative ? next : after;
    k[2] = kz;
}

// Fills p for the lanes of rays.lanes. The validity test and the permutation are
// WatertightRay's constructor's (triangle_intersection.cpp), and so are the shear quotients,
// lane by lane: kz is the axis of the largest |d| (the first of equal ones as there), kx and ky
// follow cyclically and swap when d[kz] < 0.
RAYLAB_AVX2 inline void makePacket(const RayPacket& rays, PacketRays& p) {
    __m256 f[8];
    for (int a = 0; a < 3; ++a) {
        f[a] = _mm256_load_ps(rays.origin[a]);
        f[3 + a] = _mm256_load_ps(rays.direction[a]);
    }
    f[6] = _mm256_load_ps(rays.tMin);
    f[7] = _mm256_load_ps(rays.tMax);
    const __m256* o = f;
    const __m256* d = f + 3;
    const __m256 zero = _mm256_setzero_ps();
    const __m256 valid = _mm256_and_ps(
        _mm256_and_ps(_mm256_and_ps(isFinite8(o[0]), isFinite8(o[1])),
                      _mm256_and_ps(isFinite8(o[2]), _mm256_cmp_ps(f[6], f[7], _CMP_ORD_Q))),
        _mm256_and_ps(
            _mm256_and_ps(isFinite8(d[0]), isFinite8(d[1])),
            _mm256_and_ps(isFinite8(d[2]),
                          _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(d[0], zero, _CMP_NEQ_OQ),
                                                    _mm256_cmp_ps(d[1], zero, _CMP_NEQ_OQ)),
                                       _mm256_cmp_ps(d[2], zero, _CMP_NEQ_OQ)))));
    const __m256 signMask = _mm256_set1_ps(-0.0f);
    const __m256 ax = _mm256_andnot_ps(signMask, d[0]);
    const __m256 ay = _mm256_andnot_ps(signMask, d[1]);
    const __m256 az = _mm256_andnot_ps(signMask, d[2]);
    const __m256 xy = _mm256_cmp_ps(ax, ay, _CMP_GT_OQ);
    const __m256 isX = _mm256_and_ps(xy, _mm256_cmp_ps(ax, az, _CMP_GT_OQ));
    const __m256 isY = _mm256_andnot_ps(xy, _mm256_cmp_ps(ay, az, _CMP_GT_OQ));
    const __m256 dkz = _mm256_blendv_ps(_mm256_blendv_ps(d[2], d[1], isY), d[0], isX);
    const unsigned validLanes = static_cast<unsigned>(_mm256_movemask_ps(valid)) & rays.lanes;
    const unsigned x = static_cast<unsigned>(_mm256_movemask_ps(isX));
    const unsigned y = static_cast<unsigned>(_mm256_movemask_ps(isY));
    const unsigned negative =
        static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(dkz, zero, _CMP_LT_OQ)));
    // The six permutations (kz, sign of d[kz]); the largest group wins, the first on a tie.
    const unsigned byAxis[3] = {x, y & ~x, ~(x | y)};
    int bestKz = 0;
    unsigned best = 0;
    bool bestNegative = false;
    if (validLanes != 0) { // the common case first: every valid lane shares the first one's
        const unsigned first = 1u << __builtin_ctz(validLanes);
        bestKz = (x & first) != 0 ? 0 : (y & first) != 0 ? 1 : 2;
        bestNegative = (negative & first) != 0;
        best = validLanes & byAxis[bestKz] & (bestNegative ? negative : ~negative);
    }
    if (best != validLanes) {
        best = 0;
    }
    for (int kz = 0; kz < 3 && best != validLanes; ++kz) {
        for (int neg = 0; neg < 2; ++neg) {
            const unsigned group = validLanes & byAxis[kz] & (neg != 0 ? negative : ~negative);
            if (__builtin_popcount(group) > __builtin_popcount(best)) {
                best = group;
                bestKz = kz;
                bestNegative = neg != 0;
            }
        }
    }
    p.lanes = best;
    p.others = validLanes & ~best;
    rayPermutation(bestKz, bestNegative, p.k);
    const int kx = p.k[0], ky = p.k[1];

    const __m256 one = _mm256_set1_ps(1.0f);
    const __m256 tiny = _mm256_set1_ps(1e-30f);
    for (int a = 0; a < 3; ++a) {
        p.origin[a] = o[a];
        // boxDirection (bvh_box_ray.h): +-1e-30 with d's sign where |d| < 1e-30.
        const __m256 small = _mm256_cmp_ps(_mm256_andnot_ps(signMask, d[a]), tiny, _CMP_LT_OQ);
        const __m256 boxD =
            _mm256_blendv_ps(d[a], _mm256_or_ps(tiny, _mm256_and_ps(signMask, d[a])), small);
        p.inverse[a] = _mm256_div_ps(one, boxD);
        p.originK[a] = o[p.k[a]];
        p.vertexOffset[a] = p.k[a] * kWideLanes;
    }
    // As WatertightRay: shearX = d[kx] / d[kz], shearY = d[ky] / d[kz], shearZ = 1 / d[kz].
    p.shearX = _mm256_div_ps(d[kx], d[bestKz]);
    p.shearY = _mm256_div_ps(d[ky], d[bestKz]);
    p.shearZ = _mm256_div_ps(one, d[bestKz]);
    p.tMin = f[6];
    p.tMax = f[7];
}

} // namespace raylab
