#pragma once
// What the 16-ray and 64-ray packet traversals share (internal to bvh_packet16_avx512.cpp and
// bvh_packet64_avx512.cpp, the only files that may include it: it runs only on CPUs with
// AVX-512F): a packet of 16 rays set up (makePacket16) with its frustum (tested against 8 boxes at
// once by bvh_packet_frustum.h), one lane's own tests of a node's children and of a block's
// triangles, and the test of a leaf's triangles against the packet's lanes (testLeaf).

#include "bvh/build/bvh_collapse.h"
#include "bvh/traverse/bvh_block_ray.h"
#include "bvh/traverse/bvh_packet16_lanes.h"
#include "bvh/traverse/bvh_packet_frustum.h"
#include "bvh/traverse/bvh_packet_traverse.h"

namespace raylab::packet16_lanes {

// Each lane's constants as floats, for tests of one lane's ray: the box test's, and the shear
// and tMax of the triangle test (whose origin in permuted order is origin[k]).
struct alignas(64) LaneScalars {
    float origin[3][kPacket16Size], inverse[3][kPacket16Size], tMin[kPacket16Size];
    float shear[3][kPacket16Size], tMax[kPacket16Size];
};

// The 16 rays.
struct Packet16 {
    PacketRays16 rays;
    unsigned lanes = 0;  // 16 bits: the lanes traced
    unsigned others = 0; // valid lanes of another permutation (single-ray path)
    Frustum frustum;
    LaneScalars scalars;
};

RAYLAB_AVX512 inline void makeFrustum(Packet16& p) {
    Frustum& f = p.frustum;
    const __mmask16 lanes = static_cast<__mmask16>(p.lanes);
    f.valid = p.lanes != 0;
    for (int a = 0; a < 3 && f.valid; ++a) {
        const unsigned negative =
            _mm512_mask_cmp_ps_mask(lanes, p.rays.inverse[a], _mm512_setzero_ps(), _CMP_LT_OQ);
        f.valid = negative == 0 || negative == p.lanes;
        const int nearIsUpper = negative != 0 ? 1 : 0;
        // lower[a] starts at float a * 8, upper[a] at 24 + a * 8.
        f.nearOffset[a] = nearIsUpper * 24 + a * kWideLanes;
        f.farOffset[a] = (1 - nearIsUpper) * 24 + a * kWideLanes;
        // Lanes that share one origin (a camera packet's) have it as both bounds: no reductions.
        const float first = p.scalars.origin[a][__builtin_ctz(p.lanes)];
        const bool shared = _mm512_mask_cmp_ps_mask(lanes, p.rays.origin[a], _mm512_set1_ps(first),
                                                    _CMP_NEQ_UQ) == 0;
        const float originMin = shared ? first : _mm512_mask_reduce_min_ps(lanes, p.rays.origin[a]);
        const float originMax = shared ? first : _mm512_mask_reduce_max_ps(lanes, p.rays.origin[a]);
        // Towards +a the near distance is smallest from the largest origin, the far distance
        // largest from the smallest one; towards -a the other way round.
        f.nearOrigin[a] = _mm256_set1_ps(nearIsUpper != 0 ? originMin : originMax);
        f.farOrigin[a] = _mm256_set1_ps(nearIsUpper != 0 ? originMax : originMin);
        f.inverseMin[a] = _mm256_set1_ps(_mm512_mask_reduce_min_ps(lanes, p.rays.inverse[a]));
        f.inverseMax[a] = _mm256_set1_ps(_mm512_mask_reduce_max_ps(lanes, p.rays.inverse[a]));
    }
    f.tMin = _mm256_set1_ps(_mm512_mask_reduce_min_ps(lanes, p.rays.tMin));
}

// The children lane l's own ray enters before `limit` (packet_lanes::laneChildren).
RAYLAB_AVX512 inline unsigned laneChildren(const BvhWideNode& node, const LaneScalars& s, int l,
                                           float limit) {
    const float origin[3] = {s.origin[0][l], s.origin[1][l], s.origin[2][l]};
    const float inverse[3] = {s.inverse[0][l], s.inverse[1][l], s.inverse[2][l]};
    return packet_lanes::laneChildren(node, origin, inverse, s.tMin[l], limit);
}

// Sets up the 16 rays: each half's packet (makePacket: the valid lanes sharing its most common
// permutation), joined; at once when all valid lanes share one (makeSharedPacket16). False when
// the halves' packets have different permutations.
RAYLAB_AVX512 inline bool makePacket16(const RayPacket& low, const RayPacket& high, Packet16& p) {
    if (makeSharedPacket16(low, high, p.rays, p.lanes)) {
        p.others = 0;
    } else {
        PacketRays half[2];
        makePacket(low, half[0]);
        makePacket(high, half[1]);
        PacketRays& a = half[0];
        PacketRays& b = half[1];
        if (a.lanes != 0 && b.lanes != 0 &&
            (a.k[0] != b.k[0] || a.k[1] != b.k[1] || a.k[2] != b.k[2])) {
            return false;
        }
        // A half without lanes takes the other's permutation: its registers are never read.
        PacketRays& empty = a.lanes == 0 ? a : b;
        const PacketRays& full = a.lanes == 0 ? b : a;
        if (empty.lanes == 0) {
            for (int i = 0; i < 3; ++i) {
                empty.k[i] = full.k[i];
                empty.vertexOffset[i] = full.vertexOffset[i];
                empty.originK[i] = full.originK[i];
            }
            empty.shearX = full.shearX;
            empty.shearY = full.shearY;
            empty.shearZ = full.shearZ;
        }
        p.lanes = a.lanes | b.lanes << kPacketSize;
        p.others = a.others | b.others << kPacketSize;
        joinPacket(a, b, low, high, p.rays);
    }
    for (int axis = 0; axis < 3; ++axis) {
        _mm512_store_ps(p.scalars.origin[axis], p.rays.origin[axis]);
        _mm512_store_ps(p.scalars.inverse[axis], p.rays.inverse[axis]);
    }
    _mm512_store_ps(p.scalars.tMin, p.rays.tMin);
    _mm512_store_ps(p.scalars.shear[0], p.rays.shearX);
    _mm512_store_ps(p.scalars.shear[1], p.rays.shearY);
    _mm512_store_ps(p.scalars.shear[2], p.rays.shearZ);
    _mm512_store_ps(p.scalars.tMax, p.rays.tMax);
    makeFrustum(p);
    return true;
}

// Lane l's ray with the single-ray traversal's constants (the same values: makePacket16's
// quotients are WatertightRay's, lane by lane).
RAYLAB_AVX512 inline BlockRay laneBlockRay(const Packet16& p, int l) {
    BlockRay r;
    for (int a = 0; a < 3; ++a) {
        r.vertexOffset[a] = p.rays.vertexOffset[a];
        r.originK[a] = _mm256_set1_ps(p.scalars.origin[r.vertexOffset[a] / kWideLanes][l]);
    }
    r.shearX = _mm256_set1_ps(p.scalars.shear[0][l]);
    r.shearY = _mm256_set1_ps(p.scalars.shear[1][l]);
    r.shearZ = _mm256_set1_ps(p.scalars.shear[2][l]);
    r.tMin = _mm256_set1_ps(p.scalars.tMin[l]);
    r.tMax = _mm256_set1_ps(p.scalars.tMax[l]);
    return r;
}

// The 8 triangles of a block against lane l's ray in one test (the single-ray traversal's,
// bvh_block_ray.h), each hit kept in best for that lane when closer by the (t, triangle) rule:
// what keepTriangle16 would keep for the lane, triangle by triangle.
RAYLAB_AVX512 inline void keepBlockLane(PacketBest16& best, const BvhTriangleBlock& block,
                                        const Packet16& p, int l) {
    const LaneHits h = intersectBlock(block, laneBlockRay(p, l));
    if ((h.hits | h.exact) == 0) {
        return;
    }
    const __m512i lane = _mm512_set1_epi32(l);
    LaneBest laneBest{_mm512_cvtss_f32(_mm512_permutexvar_ps(lane, best.t)),
                      static_cast<uint32_t>(_mm_cvtsi128_si32(
                          _mm512_castsi512_si128(_mm512_permutexvar_epi32(lane, best.triangle)))),
                      0.0f, 0.0f, 1.0f}; // e1, e2, det: written with t
    if (keepBlockHits(laneBest, block, h, rayOf(p.rays, l))) {
        const auto only = static_cast<__mmask16>(1u << l);
        best.t = _mm512_mask_mov_ps(best.t, only, _mm512_set1_ps(laneBest.t));
        best.e1 = _mm512_mask_mov_ps(best.e1, only, _mm512_set1_ps(laneBest.e1));
        best.e2 = _mm512_mask_mov_ps(best.e2, only, _mm512_set1_ps(laneBest.e2));
        best.det = _mm512_mask_mov_ps(best.det, only, _mm512_set1_ps(laneBest.det));
        best.triangle = _mm512_mask_mov_epi32(
            best.triangle, only, _mm512_set1_epi32(static_cast<int>(laneBest.triangle)));
    }
}

// The slot of a triangle of a block that lane l's ray hits, -1 when none (one test of the 8, as
// keepBlockLane).
RAYLAB_AVX512 inline int blockSlotHitByLane(const BvhTriangleBlock& block, const Packet16& p,
                                            int l) {
    return blockHitSlot(block, intersectBlock(block, laneBlockRay(p, l)), rayOf(p.rays, l));
}

// Tests the triangles of leaf `ref` against the lanes of `active`. Closest hit: keeps the lanes'
// closest hits in best. Any hit: adds the lanes that hit to `found`, drops them from `active`,
// leaves a triangle that one hit in `last` (when given), and stops when no lane is left. Per block,
// whichever costs fewer tests of 8 or 16 lanes:
// - each triangle some lane may hit before limitMax (frustumTriangles) against the 16 lanes;
// - or, when fewer lanes are active than that, each lane's ray against the whole block
//   (keepBlockLane, blockSlotHitByLane): the single-ray traversal's leaf test. A lone lane takes it
//   without the frustum test, which costs about as much as the block's.
template <bool closest>
RAYLAB_AVX512 inline void testLeaf(const Bvh& bvh, uint32_t ref, const Packet16& p, float limitMax,
                                   PacketBest16* best, unsigned& active, unsigned& found,
                                   LastOccluder* last) {
    const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
    for (uint32_t b = blockCount(ref); b > 0 && active != 0; --b, ++block) {
        const int lanes = __builtin_popcount(active);
        const unsigned candidates =
            distinctTriangles(*block) &
            (lanes == 1 ? 0xffu : frustumTriangles(*block, bvh.boxPad, p.frustum, limitMax));
        if (lanes < __builtin_popcount(candidates)) {
            for (unsigned m = active; m != 0; m &= m - 1) {
                const int l = __builtin_ctz(m);
                if constexpr (closest) {
                    keepBlockLane(*best, *block, p, l);
                } else if (const int slot = blockSlotHitByLane(*block, p, l); slot >= 0) {
                    found |= 1u << l;
                    active &= ~(1u << l);
                    remember(bvh, block, slot, last);
                }
            }
            continue;
        }
        for (unsigned m = candidates; m != 0 && active != 0; m &= m - 1) {
            const int tri = __builtin_ctz(m);
            if constexpr (closest) {
                keepTriangle16(*best, *block, tri, p.rays, active);
            } else {
                const unsigned hit = hitLanes16(*block, tri, p.rays, active);
                if (hit != 0) {
                    found |= hit;
                    active &= ~hit;
                    remember(bvh, block, tri, last);
                }
            }
        }
    }
}

} // namespace raylab::packet16_lanes
