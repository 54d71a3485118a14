#pragma once
// Per-lane constants of a packet of up to 8 rays (internal to bvh_packet_avx2.cpp, which is the
// only file that may include this: it uses AVX2 and must only run on CPUs that have it).
//
// The rays are loaded as eight 32-byte rows and transposed, so each field of the 8 rays is one
// register. The lanes that trace together are the valid ones (WatertightRay's test) sharing the
// most common ray permutation; the other lanes keep whatever they hold and are never read back.

#include "bvh_box_ray.h"
#include "bvh_wide.h"
#include "ray.h"
#include "watertight_avx2.h"

#include <cstddef>
#include <immintrin.h>

namespace raylab {

static_assert(sizeof(Ray) == 8 * sizeof(float) && offsetof(Ray, direction) == 12 &&
                  offsetof(Ray, tMin) == 24 && offsetof(Ray, tMax) == 28,
              "a Ray is one row of 8 floats: origin, direction, tMin, tMax");

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

// r[i] = row i (ray i) in, r[j] = field j of the 8 rays out.
RAYLAB_AVX2 inline void transpose8(__m256 (&r)[8]) {
    __m256 t[8], s[8];
    for (int i = 0; i < 8; i += 2) {
        t[i] = _mm256_unpacklo_ps(r[i], r[i + 1]);
        t[i + 1] = _mm256_unpackhi_ps(r[i], r[i + 1]);
    }
    for (int i = 0; i < 8; i += 4) {
        s[i] = _mm256_shuffle_ps(t[i], t[i + 2], _MM_SHUFFLE(1, 0, 1, 0));
        s[i + 1] = _mm256_shuffle_ps(t[i], t[i + 2], _MM_SHUFFLE(3, 2, 3, 2));
        s[i + 2] = _mm256_shuffle_ps(t[i + 1], t[i + 3], _MM_SHUFFLE(1, 0, 1, 0));
        s[i + 3] = _mm256_shuffle_ps(t[i + 1], t[i + 3], _MM_SHUFFLE(3, 2, 3, 2));
    }
    for (int i = 0; i < 4; ++i) {
        r[i] = _mm256_permute2f128_ps(s[i], s[i + 4], 0x20);
        r[i + 4] = _mm256_permute2f128_ps(s[i], s[i + 4], 0x31);
    }
}

// Lanes whose value is finite (not NaN, not +-inf).
RAYLAB_AVX2 inline __m256 isFinite8(__m256 x) {
    return _mm256_cmp_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), x), _mm256_set1_ps(kInfinity),
                         _CMP_LT_OQ);
}

// Fills p for rays[0, count), 1 <= count <= 8. The validity test and the permutation are
// WatertightRay's constructor's (triangle_intersection.cpp), and so are the shear quotients,
// lane by lane: kz is the axis of the largest |d| (the first of equal ones as there), kx and ky
// follow cyclically and swap when d[kz] < 0.
RAYLAB_AVX2 inline void makePacket(const Ray* rays, int count, PacketRays& p) {
    __m256 f[8];
    if (count == 8) {
        for (int i = 0; i < 8; ++i) {
            f[i] = _mm256_loadu_ps(&rays[i].origin.x);
        }
    } else {
        for (int i = 0; i < 8; ++i) {
            f[i] = i < count ? _mm256_loadu_ps(&rays[i].origin.x) : _mm256_setzero_ps();
        }
    }
    transpose8(f);
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
    const unsigned inPacket = (1u << count) - 1u;
    const unsigned validLanes = static_cast<unsigned>(_mm256_movemask_ps(valid)) & inPacket;
    const unsigned x = static_cast<unsigned>(_mm256_movemask_ps(isX));
    const unsigned y = static_cast<unsigned>(_mm256_movemask_ps(isY));
    const unsigned negative =
        static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(dkz, zero, _CMP_LT_OQ)));
    // The six permutations (kz, sign of d[kz]); the largest group wins, the first on a tie.
    const unsigned byAxis[3] = {x, y & ~x, ~(x | y)};
    int bestKz = 0;
    unsigned best = 0;
    bool bestNegative = false;
    for (int kz = 0; kz < 3; ++kz) {
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
    int kx = bestKz == 2 ? 0 : bestKz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (bestNegative) {
        const int swap = kx;
        kx = ky;
        ky = swap;
    }
    p.k[0] = kx;
    p.k[1] = ky;
    p.k[2] = bestKz;

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
