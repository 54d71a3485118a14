#pragma once
// The per-lane work of the AVX2 packet traversals (internal to core; only files that run on CPUs
// with AVX2 may include it): a child box of a node against the 8 rays of a PacketRays, one
// triangle of a BvhTriangleBlock against them, and the closest hit per lane kept as (t, triangle
// index), so that the order in which triangles are tested never changes an answer.

#include "bvh/bvh.h"
#include "bvh/bvh_packet.h"
#include "bvh/traverse/bvh_block_ray.h"
#include "bvh/traverse/bvh_box_ray.h"
#include "bvh/traverse/bvh_packet_setup.h"
#include "bvh/traverse/bvh_wide_refs.h"
#include "triangle_intersection.h"

namespace raylab::packet_lanes {

// Triangle `tri` of a block against every lane (watertight_avx2.h).
RAYLAB_AVX2 inline LaneHits intersectTriangle8(const BvhTriangleBlock& block, int tri,
                                               const PacketRays& p) {
    const float* v = &block.vertex[0][0][tri];
    __m256 x[3], y[3], z[3]; // sheared a, b, c; z is a[kz] etc. before scaling
    for (int k = 0; k < 3; ++k) {
        const float* q = v + k * 3 * kWideLanes;
        const __m256 dx = _mm256_sub_ps(_mm256_set1_ps(q[p.vertexOffset[0]]), p.originK[0]);
        const __m256 dy = _mm256_sub_ps(_mm256_set1_ps(q[p.vertexOffset[1]]), p.originK[1]);
        z[k] = _mm256_sub_ps(_mm256_set1_ps(q[p.vertexOffset[2]]), p.originK[2]);
        x[k] = _mm256_sub_ps(dx, _mm256_mul_ps(p.shearX, z[k]));
        y[k] = _mm256_sub_ps(dy, _mm256_mul_ps(p.shearY, z[k]));
    }
    return watertightLanes(x, y, z, p.shearZ, p.tMin, p.tMax);
}

// Spare lanes of a block repeat its first triangle (bvh_wide.h); pre-split copies of one
// triangle have equal vertices too. Either way testing it again cannot change an answer.
inline bool repeatsFirst(const BvhTriangleBlock& block, int tri) {
    return tri > 0 && block.sceneIndex[tri] == block.sceneIndex[0];
}

// The lanes of a block that do not repeat its first triangle (repeatsFirst), lane 0 among them.
RAYLAB_AVX2 inline unsigned distinctTriangles(const BvhTriangleBlock& block) {
    const __m256i index = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(block.sceneIndex));
    const __m256i first = _mm256_set1_epi32(static_cast<int>(block.sceneIndex[0]));
    const auto repeats = static_cast<unsigned>(
        _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(index, first))));
    return (~repeats & 0xffu) | 1u;
}

// Leaves slot `slot` of `block` (one of bvh's) in `last`, when given.
inline void remember(const Bvh& bvh, const BvhTriangleBlock* block, int slot, LastOccluder* last) {
    if (last != nullptr) {
        last->block = static_cast<uint32_t>(block - bvh.triangleBlocks.data());
        last->slot = slot;
    }
}

// The closest hit per lane so far: (t, triangle) decides; u and v are held as e1 and e2 until
// divided by det at the end (det = 1 for hits from intersectTriangle, whose u, v are final).
struct PacketBest {
    __m256 t, e1, e2, det;
    __m256i triangle;
};

RAYLAB_AVX2 inline void keepCloser(PacketBest& best, const LaneHits& h, unsigned lanes,
                                   uint32_t index) {
    // Unsigned index < best.triangle: compare with the sign bits flipped.
    const __m256i flip = _mm256_set1_epi32(static_cast<int>(0x80000000u));
    const __m256i lower =
        _mm256_cmpgt_epi32(_mm256_xor_si256(best.triangle, flip),
                           _mm256_set1_epi32(static_cast<int>(index ^ 0x80000000u)));
    const __m256 closer = _mm256_or_ps(
        _mm256_cmp_ps(h.t, best.t, _CMP_LT_OQ),
        _mm256_and_ps(_mm256_cmp_ps(h.t, best.t, _CMP_EQ_OQ), _mm256_castsi256_ps(lower)));
    const unsigned better = lanes & static_cast<unsigned>(_mm256_movemask_ps(closer));
    if (better == 0) {
        return;
    }
    const __m256i bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    const __m256 mask = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
        _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(better)), bits), bits));
    best.t = _mm256_blendv_ps(best.t, h.t, mask);
    best.e1 = _mm256_blendv_ps(best.e1, h.e1, mask);
    best.e2 = _mm256_blendv_ps(best.e2, h.e2, mask);
    best.det = _mm256_blendv_ps(best.det, h.det, mask);
    best.triangle = _mm256_blendv_epi8(best.triangle, _mm256_set1_epi32(static_cast<int>(index)),
                                       _mm256_castps_si256(mask));
}

// Every lane of hits: best's hit for the lanes of `lanes` that found a triangle, Hit{} for the
// others. Whole-register stores: hits is read back as registers (shadeLab8), and a register load
// of data just written lane by lane would stall on store forwarding.
RAYLAB_AVX2 inline void writeBest(const PacketBest& best, unsigned lanes, HitPacket& hits) {
    const __m256i bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    const __m256i found = _mm256_andnot_si256(
        _mm256_cmpeq_epi32(best.triangle, _mm256_set1_epi32(-1)),
        _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(lanes)), bits),
                           bits));
    const __m256 write = _mm256_castsi256_ps(found);
    const Hit none;
    _mm256_store_ps(hits.t, _mm256_blendv_ps(_mm256_set1_ps(none.t), best.t, write));
    _mm256_store_ps(
        hits.u, _mm256_blendv_ps(_mm256_set1_ps(none.u), _mm256_div_ps(best.e1, best.det), write));
    _mm256_store_ps(
        hits.v, _mm256_blendv_ps(_mm256_set1_ps(none.v), _mm256_div_ps(best.e2, best.det), write));
    _mm256_store_si256(reinterpret_cast<__m256i*>(hits.triangle),
                       _mm256_blendv_epi8(_mm256_set1_epi32(static_cast<int>(none.triangle)),
                                          best.triangle, found));
}

// Lane l's exact-fallback test of triangle `tri` (intersectTriangle itself, for `ray`), kept in
// the lane's entries of the best-hit arrays when closer by the (t, triangle index) rule; u and v
// are final, so det is 1.
inline void keepExactLane(const BvhTriangleBlock& block, int tri, const Ray& ray, int l, float* t,
                          float* e1, float* e2, float* det, uint32_t* triangle) {
    const uint32_t index = block.sceneIndex[tri];
    float tHit, u, v;
    if (intersectLane(block, tri, ray, tHit, u, v) && closerHit(tHit, index, t[l], triangle[l])) {
        t[l] = tHit;
        e1[l] = u;
        e2[l] = v;
        det[l] = 1.0f;
        triangle[l] = index;
    }
}

// Tests the exact-fallback lanes of triangle `tri` (keepExactLane) and keeps the closer hits.
RAYLAB_AVX2 inline void keepExact(PacketBest& best, const BvhTriangleBlock& block, int tri,
                                  const RayPacket& rays, unsigned lanes) {
    alignas(32) float bt[kWideLanes], e1[kWideLanes], e2[kWideLanes], det[kWideLanes];
    alignas(32) uint32_t bi[kWideLanes];
    _mm256_store_ps(bt, best.t);
    _mm256_store_ps(e1, best.e1);
    _mm256_store_ps(e2, best.e2);
    _mm256_store_ps(det, best.det);
    _mm256_store_si256(reinterpret_cast<__m256i*>(bi), best.triangle);
    for (unsigned m = lanes; m != 0; m &= m - 1) {
        const int l = __builtin_ctz(m);
        keepExactLane(block, tri, rays.ray(l), l, bt, e1, e2, det, bi);
    }
    best.t = _mm256_load_ps(bt);
    best.e1 = _mm256_load_ps(e1);
    best.e2 = _mm256_load_ps(e2);
    best.det = _mm256_load_ps(det);
    best.triangle = _mm256_load_si256(reinterpret_cast<const __m256i*>(bi));
}

// Slab test of child c's box against every lane (bvh_box_ray.h's test per lane: the near
// plane is the smaller of the two distances). Returns the lanes whose (tMin, limit] overlaps the
// box, and their entry distances.
RAYLAB_AVX2 inline unsigned hitChild(const BvhWideNode& node, int c, const PacketRays& p,
                                     __m256 limit, __m256& tNear) {
    __m256 tn = p.tMin, tf = limit;
    for (int a = 0; a < 3; ++a) {
        const __m256 t0 = _mm256_mul_ps(
            _mm256_sub_ps(_mm256_set1_ps(node.lower[a][c]), p.origin[a]), p.inverse[a]);
        const __m256 t1 = _mm256_mul_ps(
            _mm256_sub_ps(_mm256_set1_ps(node.upper[a][c]), p.origin[a]), p.inverse[a]);
        tn = _mm256_max_ps(tn, _mm256_min_ps(t0, t1));
        tf = _mm256_min_ps(tf, _mm256_max_ps(t0, t1));
    }
    tNear = tn;
    return static_cast<unsigned>(_mm256_movemask_ps(
        _mm256_cmp_ps(tn, _mm256_mul_ps(tf, _mm256_set1_ps(kBoxRoundUp)), _CMP_LE_OQ)));
}

// No hit yet in any lane.
RAYLAB_AVX2 inline PacketBest noHitYet() {
    return {_mm256_set1_ps(kInfinity), _mm256_setzero_ps(), _mm256_setzero_ps(),
            _mm256_set1_ps(1.0f), _mm256_set1_epi32(static_cast<int>(kNoTriangle))};
}

// Triangle `tri` of `block` against the lanes of `active`, kept in best where closer.
RAYLAB_AVX2 inline void keepTriangle(PacketBest& best, const BvhTriangleBlock& block, int tri,
                                     const PacketRays& p, const RayPacket& rays, unsigned active) {
    const LaneHits h = intersectTriangle8(block, tri, p);
    if ((h.hits & active) != 0) {
        keepCloser(best, h, h.hits & active, block.sceneIndex[tri]);
    }
    if ((h.exact & active) != 0) {
        keepExact(best, block, tri, rays, h.exact & active);
    }
}

// The lanes of `active` whose ray hits triangle `tri` of `block`.
RAYLAB_AVX2 inline unsigned hitLanes(const BvhTriangleBlock& block, int tri, const PacketRays& p,
                                     const RayPacket& rays, unsigned active) {
    const LaneHits h = intersectTriangle8(block, tri, p);
    unsigned hit = h.hits & active;
    for (unsigned m = h.exact & active & ~hit; m != 0; m &= m - 1) {
        const int l = __builtin_ctz(m);
        float t, u, v;
        if (intersectLane(block, tri, rays.ray(l), t, u, v)) {
            hit |= 1u << l;
        }
    }
    return hit;
}

} // namespace raylab::packet_lanes
