#pragma once
// What the AVX2 packet traversals of one 8-ray packet (bvh_packet_avx2.cpp) and of eight at once
// (bvh_packet64_avx2.cpp) share (internal to core; only files that run on CPUs with AVX2 may
// include it): a packet's culling state (its frustum, its lanes' constants and limits), one
// lane's own tests, and the test of a leaf's triangles against the packet's lanes (testLeaf).

#include "bvh/build/bvh_collapse.h"
#include "bvh/traverse/bvh_packet_frustum.h"
#include "bvh/traverse/bvh_packet_lanes.h"

namespace raylab::packet_lanes {

// The packet's frustum, its lanes' box-test constants as floats for one lane's own test of a
// node's children (laneChildren), each lane's limit (min(tMax, its closest hit so far)) and the
// largest of them. Set only where the frustum is valid.
struct PacketCulling {
    Frustum frustum;
    alignas(32) float origin[3][kPacketSize];
    alignas(32) float inverse[3][kPacketSize];
    alignas(32) float tMin[kPacketSize];
    alignas(32) float limit[kPacketSize];
    float limitMax = 0.0f;
};

RAYLAB_AVX2 inline void setLimits(const PacketRays& p, __m256 limit, PacketCulling& c) {
    if (c.frustum.valid) {
        _mm256_store_ps(c.limit, limit);
        c.limitMax = laneMax(limit, p.lanes);
    }
}

// The children of `node` that frustum `f` lets some lane enter before `limitMax` (frustumBoxes;
// 0 when none), their frustum near distances in frustumNear[0, 8), and in `firstLane` those of
// them that lane l of the packet culled by `c` enters itself (laneChildren): a traversal takes
// these with every active lane and tests only the others lane by lane. `f` is c's frustum or one
// that also bounds other packets' lanes; it must be valid.
RAYLAB_AVX2 inline unsigned frustumChildren(const BvhWideNode& node, const Frustum& f,
                                            float limitMax, const PacketCulling& c, int l,
                                            float* frustumNear, unsigned& firstLane) {
    __m256 tNear;
    const unsigned candidates = frustumBoxes(&node.lower[0][0], f, limitMax, tNear);
    firstLane = 0;
    if (candidates == 0) {
        return 0;
    }
    _mm256_store_ps(frustumNear, tNear);
    const float origin[3] = {c.origin[0][l], c.origin[1][l], c.origin[2][l]};
    const float inverse[3] = {c.inverse[0][l], c.inverse[1][l], c.inverse[2][l]};
    firstLane = candidates & laneChildren(node, origin, inverse, c.tMin[l], c.limit[l]);
    return candidates;
}

RAYLAB_AVX2 inline void makeCulling(const PacketRays& p, PacketCulling& c) {
    makeFrustum8(p, c.frustum);
    if (!c.frustum.valid) {
        return;
    }
    for (int a = 0; a < 3; ++a) {
        _mm256_store_ps(c.origin[a], p.origin[a]);
        _mm256_store_ps(c.inverse[a], p.inverse[a]);
    }
    _mm256_store_ps(c.tMin, p.tMin);
    setLimits(p, p.tMax, c);
}

// Lane l of x in all 8 lanes.
RAYLAB_AVX2 inline __m256 laneOf(__m256 x, int l) {
    return _mm256_permutevar8x32_ps(x, _mm256_set1_epi32(l));
}

// Lane l's ray with the single-ray traversal's constants (the same values: makePacket's
// quotients are WatertightRay's, lane by lane).
RAYLAB_AVX2 inline BlockRay laneBlockRay(const PacketRays& p, int l) {
    BlockRay r;
    for (int a = 0; a < 3; ++a) {
        r.originK[a] = laneOf(p.originK[a], l);
        r.vertexOffset[a] = p.vertexOffset[a];
    }
    r.shearX = laneOf(p.shearX, l);
    r.shearY = laneOf(p.shearY, l);
    r.shearZ = laneOf(p.shearZ, l);
    r.tMin = laneOf(p.tMin, l);
    r.tMax = laneOf(p.tMax, l);
    return r;
}

// The 8 triangles of a block against lane l's ray in one test (bvh_block_ray.h), each hit kept
// in best for that lane when closer by the (t, triangle) rule: what keepTriangle would keep for
// the lane, triangle by triangle.
RAYLAB_AVX2 inline void keepBlockLane(PacketBest& best, const BvhTriangleBlock& block,
                                      const PacketRays& p, const RayPacket& rays, int l) {
    const LaneHits h = intersectBlock(block, laneBlockRay(p, l));
    if ((h.hits | h.exact) == 0) {
        return;
    }
    const __m256i lane = _mm256_set1_epi32(l);
    LaneBest laneBest{_mm256_cvtss_f32(laneOf(best.t, l)),
                      static_cast<uint32_t>(
                          _mm256_cvtsi256_si32(_mm256_permutevar8x32_epi32(best.triangle, lane))),
                      0.0f, 0.0f, 1.0f}; // e1, e2, det: written with t
    if (keepBlockHits(laneBest, block, h, rays.ray(l))) {
        const __m256 only = _mm256_castsi256_ps(
            _mm256_cmpeq_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), lane));
        best.t = _mm256_blendv_ps(best.t, _mm256_set1_ps(laneBest.t), only);
        best.e1 = _mm256_blendv_ps(best.e1, _mm256_set1_ps(laneBest.e1), only);
        best.e2 = _mm256_blendv_ps(best.e2, _mm256_set1_ps(laneBest.e2), only);
        best.det = _mm256_blendv_ps(best.det, _mm256_set1_ps(laneBest.det), only);
        best.triangle = _mm256_castps_si256(_mm256_blendv_ps(
            _mm256_castsi256_ps(best.triangle),
            _mm256_castsi256_ps(_mm256_set1_epi32(static_cast<int>(laneBest.triangle))), only));
    }
}

// One block of a leaf against the lanes of `active`. Closest hit (best set): keeps the lanes'
// closest hits in best. Any hit: adds the lanes that hit to `found`, drops them from `active`,
// leaves a triangle that one hit in `last` (when given), and stops when none is left. Whichever
// takes fewer tests of 8 lanes:
// - each triangle some lane may hit before the lanes' largest limit (frustumTriangles) against
//   the lanes;
// - or, when fewer lanes are active than that, each active lane's ray against the whole block
//   (the single-ray traversal's test). A lone lane takes it without the frustum test, which
//   costs about as much as the block's.
// `bounds`, when given, are the block's triangle boxes (triangleBounds), made once for all the
// packets that test the block; else they are made here when needed.
RAYLAB_AVX2 inline void testBlock(const Bvh& bvh, const BvhTriangleBlock* block,
                                  const TriangleBounds* bounds, const PacketRays& p,
                                  const PacketCulling& cull, const RayPacket& rays,
                                  PacketBest* best, unsigned& active, unsigned& found,
                                  LastOccluder* last) {
    const int lanes = __builtin_popcount(active);
    unsigned triangles = distinctTriangles(*block);
    if (lanes != 1) {
        triangles &= bounds != nullptr
                         ? frustumTriangles(*bounds, cull.frustum, cull.limitMax)
                         : frustumTriangles(*block, bvh.boxPad, cull.frustum, cull.limitMax);
    }
    if (lanes < __builtin_popcount(triangles)) {
        for (unsigned m = active; m != 0; m &= m - 1) {
            const int l = __builtin_ctz(m);
            if (best != nullptr) {
                keepBlockLane(*best, *block, p, rays, l);
            } else if (const int slot = blockHitSlot(
                           *block, intersectBlock(*block, laneBlockRay(p, l)), rays.ray(l));
                       slot >= 0) {
                found |= 1u << l;
                active &= ~(1u << l);
                remember(bvh, block, slot, last);
            }
        }
        return;
    }
    for (unsigned m = triangles; m != 0 && active != 0; m &= m - 1) {
        const int tri = __builtin_ctz(m);
        if (best != nullptr) {
            keepTriangle(*best, *block, tri, p, rays, active);
        } else {
            const unsigned hit = hitLanes(*block, tri, p, rays, active);
            if (hit != 0) {
                found |= hit;
                active &= ~hit;
                remember(bvh, block, tri, last);
            }
        }
    }
}

// The leaf's blocks against the lanes of `active`, block by block (testBlock).
RAYLAB_AVX2 inline void testLeaf(const Bvh& bvh, uint32_t ref, const PacketRays& p,
                                 const PacketCulling& cull, const RayPacket& rays, PacketBest* best,
                                 unsigned& active, unsigned& found, LastOccluder* last) {
    const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
    for (uint32_t b = blockCount(ref); b > 0 && active != 0; --b, ++block) {
        testBlock(bvh, block, nullptr, p, cull, rays, best, active, found, last);
    }
}

} // namespace raylab::packet_lanes
