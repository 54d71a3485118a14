#pragma once
// The per-lane work of the 16-ray packets on 16 lanes at once (internal to the AVX-512 packet
// traversals, bvh_packet16_avx512.cpp and bvh_packet64_avx512.cpp through bvh_packet16_parts.h,
// the only files that may include it: it runs only on CPUs with AVX-512F): a child box of a node
// and a triangle of a BvhTriangleBlock against the 16 rays, and the closest hit per lane kept as
// (t, triangle index). Each is the 8-lane packets' own (bvh_packet_lanes.h) on twice the lanes,
// with the same operations in the same order, so the answers are theirs bit for bit.

#include "bvh/traverse/bvh_packet16_traverse.h"
#include "bvh/traverse/bvh_packet_lanes.h"
#include "watertight_avx512.h"

namespace raylab::packet16_lanes {

using namespace packet_lanes;

// Two 8-lane registers as one of 16: lo in lanes 0-7, hi in lanes 8-15.
RAYLAB_AVX512 inline __m512 join(__m256 lo, __m256 hi) {
    return _mm512_castpd_ps(
        _mm512_insertf64x4(_mm512_castps_pd(_mm512_castps256_ps512(lo)), _mm256_castps_pd(hi), 1));
}

// Lanes 0-7 (h = 0) or 8-15 (h = 1) of x. The extraction's lane index must be an immediate
// even where the optimiser does not fold h (sanitizer builds), hence the two constants.
RAYLAB_AVX512 inline __m256 half(__m512 x, int h) {
    const __m512d d = _mm512_castps_pd(x);
    return _mm256_castpd_ps(h == 0 ? _mm512_extractf64x4_pd(d, 0) : _mm512_extractf64x4_pd(d, 1));
}

// The 8 lanes of half h of a 16-lane mask.
inline unsigned halfLanes(unsigned lanes, int h) { return (lanes >> (h * kPacketSize)) & 0xffu; }

// The constants of 16 rays that share one permutation (two PacketRays with equal k), joined.
struct PacketRays16 {
    __m512 origin[3], inverse[3]; // box test
    __m512 tMin, tMax;
    __m512 originK[3]; // triangle test, as PacketRays
    __m512 shearX, shearY, shearZ;
    int vertexOffset[3];
    const RayPacket* rays[2]; // lanes 0-7, 8-15: for the exact fallback
};

// Lane l's ray (for the lanes that go to the scalar or single-ray tests).
inline Ray rayOf(const PacketRays16& p, int l) {
    return p.rays[l / kPacketSize]->ray(l % kPacketSize);
}

RAYLAB_AVX512 inline void joinPacket(const PacketRays& low, const PacketRays& high,
                                     const RayPacket& lowRays, const RayPacket& highRays,
                                     PacketRays16& p) {
    for (int a = 0; a < 3; ++a) {
        p.origin[a] = join(low.origin[a], high.origin[a]);
        p.inverse[a] = join(low.inverse[a], high.inverse[a]);
        p.originK[a] = join(low.originK[a], high.originK[a]);
        p.vertexOffset[a] = low.vertexOffset[a];
    }
    p.tMin = join(low.tMin, high.tMin);
    p.tMax = join(low.tMax, high.tMax);
    p.shearX = join(low.shearX, high.shearX);
    p.shearY = join(low.shearY, high.shearY);
    p.shearZ = join(low.shearZ, high.shearZ);
    p.rays[0] = &lowRays;
    p.rays[1] = &highRays;
}

// 8 floats of lo and 8 of hi as one register (lanes 0-7, 8-15).
RAYLAB_AVX512 inline __m512 loadJoined(const float* lo, const float* hi) {
    return join(_mm256_load_ps(lo), _mm256_load_ps(hi));
}

// Lanes whose value is finite (not NaN, not +-inf).
RAYLAB_AVX512 inline unsigned isFinite16(__m512 x) {
    return _mm512_cmp_ps_mask(_mm512_abs_ps(x), _mm512_set1_ps(kInfinity), _CMP_LT_OQ);
}

// x with the sign bit of `sign` (AVX-512F has no float or / and).
RAYLAB_AVX512 inline __m512 withSignOf(__m512 x, __m512 sign) {
    const __m512i signBit = _mm512_set1_epi32(static_cast<int>(0x80000000u));
    return _mm512_castsi512_ps(_mm512_or_si512(
        _mm512_castps_si512(x), _mm512_and_si512(_mm512_castps_si512(sign), signBit)));
}

// Sets up p for the 16 rays of low (lanes 0-7) and high (lanes 8-15) when every valid lane of
// their lanes shares the first valid lane's ray permutation, the common case of coherent rays:
// then each half's makePacket would pick that permutation for all its valid lanes, and p is the
// join of the two (joinPacket), computed on 16 lanes at once. Returns the valid lanes (`lanes`,
// 16 bits), or false when they do not share one permutation and nothing of p is set. The
// validity test, the permutation and every quotient are makePacket's, lane by lane.
RAYLAB_AVX512 inline bool makeSharedPacket16(const RayPacket& low, const RayPacket& high,
                                             PacketRays16& p, unsigned& lanes) {
    __m512 d[3];
    for (int a = 0; a < 3; ++a) {
        p.origin[a] = loadJoined(low.origin[a], high.origin[a]);
        d[a] = loadJoined(low.direction[a], high.direction[a]);
    }
    p.tMin = loadJoined(low.tMin, high.tMin);
    p.tMax = loadJoined(low.tMax, high.tMax);
    const __m512 zero = _mm512_setzero_ps();
    const unsigned valid =
        isFinite16(p.origin[0]) & isFinite16(p.origin[1]) & isFinite16(p.origin[2]) &
        _mm512_cmp_ps_mask(p.tMin, p.tMax, _CMP_ORD_Q) & isFinite16(d[0]) & isFinite16(d[1]) &
        isFinite16(d[2]) &
        (_mm512_cmp_ps_mask(d[0], zero, _CMP_NEQ_OQ) | _mm512_cmp_ps_mask(d[1], zero, _CMP_NEQ_OQ) |
         _mm512_cmp_ps_mask(d[2], zero, _CMP_NEQ_OQ));
    lanes = valid & (low.lanes | high.lanes << kPacketSize);
    const __m512 ax = _mm512_abs_ps(d[0]);
    const __m512 ay = _mm512_abs_ps(d[1]);
    const __m512 az = _mm512_abs_ps(d[2]);
    const unsigned xy = _mm512_cmp_ps_mask(ax, ay, _CMP_GT_OQ);
    const unsigned x = xy & _mm512_cmp_ps_mask(ax, az, _CMP_GT_OQ);
    const unsigned y = ~xy & _mm512_cmp_ps_mask(ay, az, _CMP_GT_OQ);
    const __m512 dkz = _mm512_mask_mov_ps(_mm512_mask_mov_ps(d[2], static_cast<__mmask16>(y), d[1]),
                                          static_cast<__mmask16>(x), d[0]);
    const unsigned negative = _mm512_cmp_ps_mask(dkz, zero, _CMP_LT_OQ);
    int kz = 2;
    bool kzNegative = false;
    if (lanes != 0) {
        const unsigned first = lanes & (0u - lanes);
        kz = (x & first) != 0 ? 0 : (y & first) != 0 ? 1 : 2;
        kzNegative = (negative & first) != 0;
        const unsigned byAxis = kz == 0 ? x : kz == 1 ? y & ~x : ~(x | y);
        if ((lanes & byAxis & (kzNegative ? negative : ~negative)) != lanes) {
            return false;
        }
    }
    int k[3];
    rayPermutation(kz, kzNegative, k);
    const __m512 one = _mm512_set1_ps(1.0f);
    const __m512 tiny = _mm512_set1_ps(1e-30f);
    for (int a = 0; a < 3; ++a) {
        // boxDirection (bvh_box_ray.h): +-1e-30 with d's sign where |d| < 1e-30.
        const __mmask16 small = _mm512_cmp_ps_mask(_mm512_abs_ps(d[a]), tiny, _CMP_LT_OQ);
        p.inverse[a] = _mm512_div_ps(one, _mm512_mask_mov_ps(d[a], small, withSignOf(tiny, d[a])));
        p.originK[a] = p.origin[k[a]];
        p.vertexOffset[a] = k[a] * kWideLanes;
    }
    p.shearX = _mm512_div_ps(d[k[0]], d[kz]);
    p.shearY = _mm512_div_ps(d[k[1]], d[kz]);
    p.shearZ = _mm512_div_ps(one, d[kz]);
    p.rays[0] = &low;
    p.rays[1] = &high;
    return true;
}

// Slab test of child c's box against the 16 lanes (hitChild's on each lane): the lanes whose
// (tMin, limit] overlaps the box, and their entry distances.
RAYLAB_AVX512 inline unsigned hitChild16(const BvhWideNode& node, int c, const PacketRays16& p,
                                         __m512 limit, __m512& tNear) {
    __m512 tn = p.tMin, tf = limit;
    for (int a = 0; a < 3; ++a) {
        const __m512 t0 = _mm512_mul_ps(
            _mm512_sub_ps(_mm512_set1_ps(node.lower[a][c]), p.origin[a]), p.inverse[a]);
        const __m512 t1 = _mm512_mul_ps(
            _mm512_sub_ps(_mm512_set1_ps(node.upper[a][c]), p.origin[a]), p.inverse[a]);
        tn = _mm512_max_ps(tn, _mm512_min_ps(t0, t1));
        tf = _mm512_min_ps(tf, _mm512_max_ps(t0, t1));
    }
    tNear = tn;
    return _mm512_cmp_ps_mask(tn, _mm512_mul_ps(tf, _mm512_set1_ps(kBoxRoundUp)), _CMP_LE_OQ);
}

// Triangle `tri` of a block against every lane (intersectTriangle8's arithmetic).
RAYLAB_AVX512 inline LaneHits16 intersectTriangle16(const BvhTriangleBlock& block, int tri,
                                                    const PacketRays16& p) {
    const float* v = &block.vertex[0][0][tri];
    __m512 x[3], y[3], z[3];
    for (int k = 0; k < 3; ++k) {
        const float* q = v + k * 3 * kWideLanes;
        const __m512 dx = _mm512_sub_ps(_mm512_set1_ps(q[p.vertexOffset[0]]), p.originK[0]);
        const __m512 dy = _mm512_sub_ps(_mm512_set1_ps(q[p.vertexOffset[1]]), p.originK[1]);
        z[k] = _mm512_sub_ps(_mm512_set1_ps(q[p.vertexOffset[2]]), p.originK[2]);
        x[k] = _mm512_sub_ps(dx, _mm512_mul_ps(p.shearX, z[k]));
        y[k] = _mm512_sub_ps(dy, _mm512_mul_ps(p.shearY, z[k]));
    }
    return watertightLanes16(x, y, z, p.shearZ, p.tMin, p.tMax);
}

// The closest hit per lane so far, as PacketBest on 16 lanes.
struct PacketBest16 {
    __m512 t, e1, e2, det;
    __m512i triangle;
};

RAYLAB_AVX512 inline PacketBest16 noHitYet16() {
    return {_mm512_set1_ps(kInfinity), _mm512_setzero_ps(), _mm512_setzero_ps(),
            _mm512_set1_ps(1.0f), _mm512_set1_epi32(static_cast<int>(kNoTriangle))};
}

RAYLAB_AVX512 inline void keepCloser16(PacketBest16& best, const LaneHits16& h, unsigned lanes,
                                       uint32_t index) {
    const __m512i candidate = _mm512_set1_epi32(static_cast<int>(index));
    const unsigned lower = _mm512_cmpgt_epu32_mask(best.triangle, candidate);
    const unsigned closer = _mm512_cmp_ps_mask(h.t, best.t, _CMP_LT_OQ) |
                            (_mm512_cmp_ps_mask(h.t, best.t, _CMP_EQ_OQ) & lower);
    const __mmask16 better = static_cast<__mmask16>(lanes & closer);
    if (better == 0) {
        return;
    }
    best.t = _mm512_mask_mov_ps(best.t, better, h.t);
    best.e1 = _mm512_mask_mov_ps(best.e1, better, h.e1);
    best.e2 = _mm512_mask_mov_ps(best.e2, better, h.e2);
    best.det = _mm512_mask_mov_ps(best.det, better, h.det);
    best.triangle = _mm512_mask_mov_epi32(best.triangle, better, candidate);
}

// Tests the exact-fallback lanes of triangle `tri` (keepExactLane) and keeps the closer hits.
RAYLAB_AVX512 inline void keepExact16(PacketBest16& best, const BvhTriangleBlock& block, int tri,
                                      const PacketRays16& p, unsigned lanes) {
    alignas(64) float bt[kPacket16Size], e1[kPacket16Size], e2[kPacket16Size], det[kPacket16Size];
    alignas(64) uint32_t bi[kPacket16Size];
    _mm512_store_ps(bt, best.t);
    _mm512_store_ps(e1, best.e1);
    _mm512_store_ps(e2, best.e2);
    _mm512_store_ps(det, best.det);
    _mm512_store_si512(bi, best.triangle);
    for (unsigned m = lanes; m != 0; m &= m - 1) {
        const int l = __builtin_ctz(m);
        keepExactLane(block, tri, rayOf(p, l), l, bt, e1, e2, det, bi);
    }
    best.t = _mm512_load_ps(bt);
    best.e1 = _mm512_load_ps(e1);
    best.e2 = _mm512_load_ps(e2);
    best.det = _mm512_load_ps(det);
    best.triangle = _mm512_load_si512(bi);
}

// Triangle `tri` of `block` against the lanes of `active`, kept in best where closer.
RAYLAB_AVX512 inline void keepTriangle16(PacketBest16& best, const BvhTriangleBlock& block, int tri,
                                         const PacketRays16& p, unsigned active) {
    const LaneHits16 h = intersectTriangle16(block, tri, p);
    if ((h.hits & active) != 0) {
        keepCloser16(best, h, h.hits & active, block.sceneIndex[tri]);
    }
    if ((h.exact & active) != 0) {
        keepExact16(best, block, tri, p, h.exact & active);
    }
}

// The lanes of `active` whose ray hits triangle `tri` of `block`.
RAYLAB_AVX512 inline unsigned hitLanes16(const BvhTriangleBlock& block, int tri,
                                         const PacketRays16& p, unsigned active) {
    const LaneHits16 h = intersectTriangle16(block, tri, p);
    unsigned hit = h.hits & active;
    for (unsigned m = h.exact & active & ~hit; m != 0; m &= m - 1) {
        const int l = __builtin_ctz(m);
        float t, u, v;
        if (intersectLane(block, tri, rayOf(p, l), t, u, v)) {
            hit |= 1u << l;
        }
    }
    return hit;
}

// Half h of best, as the 8-lane packets keep it (for writeBest).
RAYLAB_AVX512 inline PacketBest halfOf(const PacketBest16& best, int h) {
    const __m512d triangle = _mm512_castsi512_pd(best.triangle);
    return {half(best.t, h), half(best.e1, h), half(best.e2, h), half(best.det, h),
            _mm256_castpd_si256(h == 0 ? _mm512_extractf64x4_pd(triangle, 0)
                                       : _mm512_extractf64x4_pd(triangle, 1))};
}

} // namespace raylab::packet16_lanes
