// Packet traversal of the 8-wide BVH for 16 rays (AVX-512F: each box and triangle test covers
// the 16 lanes at once, bvh_packet16_lanes.h). For coherent rays a node costs about what it
// costs one ray, as in Embree's coherent packets:
// - a frustum (the interval of the lanes' origins and inverse directions) tests all 8 children
//   at once and leaves out every child no lane can enter;
// - when it leaves out all 8, the visit ends there (14-39% of a camera packet's node visits);
// - the first active lane's own ray tests the 8 children; a candidate it enters is taken with
//   every active lane (a superset of the lanes that enter it) and the frustum's entry distance;
// - only the other candidates are tested lane by lane (hitChild16);
// - in a leaf, the frustum leaves out the triangles whose (padded) bounding box no lane can
//   enter, and each other triangle is tested against the active lanes; where fewer lanes reach
//   a block than it has such triangles, each lane's ray is tested against the block's 8
//   triangles at once instead (the single-ray traversal's test, bvh_block_ray.h).
// Each node's children are prefetched as soon as they are taken (prefetchChild). Any hit with a
// LastOccluder (bvh_packet.h) first tests the triangle that occluded a lane of an earlier packet
// against all 16 lanes, traverses only for the lanes it leaves open, and remembers a triangle
// that a lane hits in a leaf.
// Keeping a box or a triangle for a lane that misses it costs time, never an answer.
//
// Exactness is the 8-lane packets' (bvh_packet_avx2.cpp), with their helpers on 16 lanes: the
// lanes traced are those makePacket would pick for each half (makePacket16), and the halves are
// traced together only when they share the ray permutation (else each is its own 8-lane packet);
// triangles go through intersectTriangle16 / keepTriangle16 / hitLanes16, so t, u, v and the
// triangle are intersectTriangle's, lanes with an edge function of exactly zero go to
// intersectTriangle itself, a lane keeps the minimum of (t, triangle index), and a box is dropped
// for a lane only when it starts beyond that lane's own closest hit (kBoxRoundUp): every culling
// test above is a superset of the lanes' own slab tests.
//
// Also here: a frustum block's candidate triangles (bvh_frustum.h) tested against two packets'
// 16 lanes at once, with the same triangle test and rule.

// GCC 12's AVX-512 intrinsics start from _mm512_undefined_*() values, which -Wuninitialized
// reports inside the intrinsics' headers: silenced before the first include of them.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "bvh/traverse/bvh_packet16_traverse.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/build/bvh_collapse.h"
#include "bvh/traverse/bvh_block_ray.h"
#include "bvh/traverse/bvh_packet16_lanes.h"
#include "bvh/traverse/bvh_packet_traverse.h"

namespace raylab {

namespace {

using namespace packet16_lanes;

// Bounds of the 16 rays' box test, for all 8 children of a node at once: per axis, the interval
// of the lanes' origins and of their inverse directions, so that for every lane
// (bound - origin) * inverse lies within [min, max] of the products at the intervals' ends
// (float subtraction and multiplication round monotonically). Valid when, per axis, every lane's
// inverse has one sign: then the near bound is the same plane of the box for all of them.
struct Frustum {
    bool valid = false;
    int nearOffset[3], farOffset[3];    // into BvhWideNode's floats, as in bvh_traverse_avx2.cpp
    __m256 nearOrigin[3], farOrigin[3]; // the origins that make (bound - origin) smallest, largest
    __m256 inverseMin[3], inverseMax[3];
    __m256 tMin; // the lanes' smallest tMin
};

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

// Of 8 boxes given as lower[3][8] then upper[3][8] floats (BvhWideNode's layout), those some
// lane may enter before `limitMax` (the lanes' largest limit): a superset of the boxes any lane's
// own slab test keeps (hitChild16), since each lane's near distance is at least the frustum's
// and its far distance at most the frustum's. Also their frustum near distances.
RAYLAB_AVX512 inline unsigned frustumBoxes(const float* bounds, const Frustum& f, float limitMax,
                                           __m256& tNear) {
    __m256 tn = f.tMin, tf = _mm256_set1_ps(limitMax);
    for (int a = 0; a < 3; ++a) {
        const __m256 xn = _mm256_sub_ps(_mm256_load_ps(bounds + f.nearOffset[a]), f.nearOrigin[a]);
        const __m256 xf = _mm256_sub_ps(_mm256_load_ps(bounds + f.farOffset[a]), f.farOrigin[a]);
        tn = _mm256_max_ps(tn, _mm256_min_ps(_mm256_mul_ps(xn, f.inverseMin[a]),
                                             _mm256_mul_ps(xn, f.inverseMax[a])));
        tf = _mm256_min_ps(tf, _mm256_max_ps(_mm256_mul_ps(xf, f.inverseMin[a]),
                                             _mm256_mul_ps(xf, f.inverseMax[a])));
    }
    tNear = tn;
    return static_cast<unsigned>(_mm256_movemask_ps(
        _mm256_cmp_ps(tn, _mm256_mul_ps(tf, _mm256_set1_ps(kBoxRoundUp)), _CMP_LE_OQ)));
}

// The triangles of a block that some lane may hit before `limitMax`: those whose bounding box,
// widened by `pad` (Bvh::boxPad) as every node box is, passes frustumBoxes (a ray the watertight
// test finds on a triangle enters that box, as it enters every node box holding the triangle);
// all 8 without a valid frustum.
RAYLAB_AVX512 inline unsigned frustumTriangles(const BvhTriangleBlock& block, const Frustum& f,
                                               float pad, float limitMax) {
    if (!f.valid) {
        return 0xffu;
    }
    alignas(32) float bounds[2][3][kWideLanes];
    for (int a = 0; a < 3; ++a) {
        const __m256 v0 = _mm256_load_ps(block.vertex[0][a]);
        const __m256 v1 = _mm256_load_ps(block.vertex[1][a]);
        const __m256 v2 = _mm256_load_ps(block.vertex[2][a]);
        const __m256 widen = _mm256_set1_ps(pad);
        _mm256_store_ps(bounds[0][a],
                        _mm256_sub_ps(_mm256_min_ps(_mm256_min_ps(v0, v1), v2), widen));
        _mm256_store_ps(bounds[1][a],
                        _mm256_add_ps(_mm256_max_ps(_mm256_max_ps(v0, v1), v2), widen));
    }
    __m256 tNear;
    return frustumBoxes(&bounds[0][0][0], f, limitMax, tNear);
}

// The children lane l's own ray enters before limit[l] (bvh_traverse_avx2.cpp's hitChildren for
// that one ray, with plain min and max of the two planes so that it holds for either sign).
RAYLAB_AVX512 inline unsigned laneChildren(const BvhWideNode& node, const LaneScalars& s, int l,
                                           float limit) {
    __m256 tn = _mm256_set1_ps(s.tMin[l]), tf = _mm256_set1_ps(limit);
    for (int a = 0; a < 3; ++a) {
        const __m256 o = _mm256_set1_ps(s.origin[a][l]);
        const __m256 inv = _mm256_set1_ps(s.inverse[a][l]);
        const __m256 t0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.lower[a]), o), inv);
        const __m256 t1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.upper[a]), o), inv);
        tn = _mm256_max_ps(tn, _mm256_min_ps(t0, t1));
        tf = _mm256_min_ps(tf, _mm256_max_ps(t0, t1));
    }
    return static_cast<unsigned>(_mm256_movemask_ps(
        _mm256_cmp_ps(tn, _mm256_mul_ps(tf, _mm256_set1_ps(kBoxRoundUp)), _CMP_LE_OQ)));
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

struct alignas(64) PacketEntry16 {
    __m512 tNear; // per lane, at most the lane's entry distance
    uint32_t ref;
    unsigned lanes; // a superset of the lanes whose ray enters the box
};

// The children of a node that some lane of `active` may enter (the header comment says how),
// each prefetched (prefetchChild), sorted nearest last by the entry distance of their first lane
// when `ordered` (closest hit), else in slot order (any hit), as hitChildren of
// bvh_packet_avx2.cpp. Returns how many.
template <bool ordered>
RAYLAB_AVX512 inline int hitChildren16(const Bvh& bvh, const BvhWideNode& node, const Packet16& p,
                                       __m512 limit, const float* laneLimit, float limitMax,
                                       unsigned active, PacketEntry16* out) {
    int n = 0;
    float key[kWideLanes];
    __m256 frustumNear = _mm256_setzero_ps();
    unsigned candidates = 0xffu, firstLane = 0;
    alignas(32) float fn[kWideLanes];
    if (p.frustum.valid) {
        candidates = frustumBoxes(&node.lower[0][0], p.frustum, limitMax, frustumNear);
        if (candidates == 0) {
            return 0; // no lane enters a child
        }
        _mm256_store_ps(fn, frustumNear);
        const int l = __builtin_ctz(active);
        firstLane = candidates & laneChildren(node, p.scalars, l, laneLimit[l]);
    }
    for (unsigned m = candidates; m != 0; m &= m - 1) {
        const int c = __builtin_ctz(m);
        if (node.child[c] == kWideEmpty) {
            continue;
        }
        __m512 tNear;
        unsigned lanes;
        if ((firstLane >> c) & 1u) {
            tNear = _mm512_set1_ps(fn[c]);
            lanes = active;
        } else {
            lanes = hitChild16(node, c, p.rays, limit, tNear) & active;
        }
        if (lanes == 0) {
            continue;
        }
        prefetchChild(bvh, node.child[c]);
        if constexpr (!ordered) {
            out[n++] = PacketEntry16{tNear, node.child[c], lanes};
            continue;
        }
        const float k =
            _mm512_cvtss_f32(_mm512_permutexvar_ps(_mm512_set1_epi32(__builtin_ctz(lanes)), tNear));
        int i = n++;
        for (; i > 0 && key[i - 1] < k; --i) {
            key[i] = key[i - 1];
            out[i] = out[i - 1];
        }
        key[i] = k;
        out[i] = PacketEntry16{tNear, node.child[c], lanes};
    }
    return n;
}

// Goes on with the last of a node's n > 0 hit children, written at stack[size, size + n), and
// keeps the others pushed.
RAYLAB_AVX512 inline void descend16(int n, const PacketEntry16* stack, int& size, uint32_t& ref,
                                    unsigned& active) {
    size += n - 1;
    ref = stack[size].ref;
    active = stack[size].lanes;
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

// Leaves slot `slot` of `block` (one of bvh's) in `last`, when given.
inline void remember(const Bvh& bvh, const BvhTriangleBlock* block, int slot, LastOccluder* last) {
    if (last != nullptr) {
        last->block = static_cast<uint32_t>(block - bvh.triangleBlocks.data());
        last->slot = slot;
    }
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
            (lanes == 1 ? 0xffu : frustumTriangles(*block, p.frustum, bvh.boxPad, limitMax));
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

RAYLAB_AVX512 unsigned closestHit16Avx512(const Bvh& bvh, const Packet16& p, HitPacket* hits[2]) {
    PacketBest16 best = noHitYet16();
    __m512 limit = p.rays.tMax; // per lane: min(tMax, best.t)
    float limitMax = _mm512_mask_reduce_max_ps(static_cast<__mmask16>(p.lanes), limit);
    alignas(64) float laneLimit[kPacket16Size];
    _mm512_store_ps(laneLimit, limit);
    const __m512 roundUp = _mm512_set1_ps(kBoxRoundUp);
    PacketEntry16 stack[kWideStackSize + 1]; // + 1: a node's children are written above the top
    int size = 0;
    uint32_t ref = 0;
    unsigned active = p.lanes;
    for (;;) {
        if (!isLeaf(ref)) {
            const int n = hitChildren16<true>(bvh, bvh.wideNodes[ref], p, limit, laneLimit,
                                              limitMax, active, stack + size);
            if (n > 0) {
                descend16(n, stack, size, ref, active);
                continue;
            }
        } else {
            unsigned found = 0;
            testLeaf<true>(bvh, ref, p, limitMax, &best, active, found, nullptr);
            limit = _mm512_min_ps(p.rays.tMax, best.t);
            limitMax = _mm512_mask_reduce_max_ps(static_cast<__mmask16>(p.lanes), limit);
            _mm512_store_ps(laneLimit, limit);
        }
        // Next: the nearest pending entry that some lane may still find a closer hit in.
        for (;;) {
            if (size == 0) {
                for (int h = 0; h < 2; ++h) {
                    writeBest(halfOf(best, h), halfLanes(p.lanes, h), *hits[h]);
                }
                return p.others;
            }
            const PacketEntry16& e = stack[--size];
            const unsigned open =
                e.lanes & _mm512_cmp_ps_mask(e.tNear, _mm512_mul_ps(limit, roundUp), _CMP_LE_OQ);
            if (open != 0) {
                ref = e.ref;
                active = open;
                break;
            }
        }
    }
}

RAYLAB_AVX512 unsigned anyHit16Avx512(const Bvh& bvh, const Packet16& p, LastOccluder* last) {
    unsigned found = 0; // lanes with a hit
    if (last != nullptr && last->block < bvh.triangleBlocks.size()) {
        found = hitLanes16(bvh.triangleBlocks[last->block], last->slot & (kWideLanes - 1), p.rays,
                           p.lanes);
        if (found == p.lanes) {
            return found;
        }
    }
    const float tMaxMax = _mm512_mask_reduce_max_ps(static_cast<__mmask16>(p.lanes), p.rays.tMax);
    alignas(64) float laneTMax[kPacket16Size];
    _mm512_store_ps(laneTMax, p.rays.tMax);
    PacketEntry16 stack[kWideStackSize + 1]; // + 1: a node's children are written above the top
    int size = 0;
    uint32_t ref = 0;
    unsigned active = p.lanes & ~found;
    for (;;) {
        if (!isLeaf(ref)) {
            const int n = hitChildren16<false>(bvh, bvh.wideNodes[ref], p, p.rays.tMax, laneTMax,
                                               tMaxMax, active, stack + size);
            if (n > 0) {
                descend16(n, stack, size, ref, active);
                continue;
            }
        } else {
            testLeaf<false>(bvh, ref, p, tMaxMax, nullptr, active, found, last);
            if (found == p.lanes) {
                return found;
            }
        }
        // Next: a pending entry with a lane still unanswered.
        for (;;) {
            if (size == 0) {
                return found;
            }
            const PacketEntry16& e = stack[--size];
            if ((e.lanes & ~found) != 0) {
                ref = e.ref;
                active = e.lanes & ~found;
                break;
            }
        }
    }
}

} // namespace

RAYLAB_AVX512 unsigned closestHitPacket16(const Bvh& bvh, const RayPacket& low,
                                          const RayPacket& high, HitPacket& lowHits,
                                          HitPacket& highHits) {
    Packet16 p;
    if (!makePacket16(low, high, p)) {
        return closestHitPacket(bvh, low, lowHits) | closestHitPacket(bvh, high, highHits)
                                                         << kPacketSize;
    }
    if (p.lanes == 0) {
        lowHits.clear();
        highHits.clear();
        return p.others;
    }
    HitPacket* hits[2] = {&lowHits, &highHits};
    return closestHit16Avx512(bvh, p, hits);
}

RAYLAB_AVX512 unsigned anyHitPacket16(const Bvh& bvh, const RayPacket& low, const RayPacket& high,
                                      unsigned& occluded, LastOccluder* last) {
    Packet16 p;
    if (!makePacket16(low, high, p)) {
        unsigned lowOccluded = 0, highOccluded = 0;
        const unsigned others = anyHitPacket(bvh, low, lowOccluded) |
                                anyHitPacket(bvh, high, highOccluded) << kPacketSize;
        occluded = lowOccluded | highOccluded << kPacketSize;
        return others;
    }
    occluded = p.lanes != 0 ? anyHit16Avx512(bvh, p, last) : 0u;
    return p.others;
}

RAYLAB_AVX512 bool closestHitCandidates16(const Bvh& bvh, const FrustumCandidates& candidates,
                                          const RayPacket& low, const RayPacket& high,
                                          HitPacket& lowHits, HitPacket& highHits) {
    PacketRays16 p;
    unsigned lanes = 0;
    if (!makeSharedPacket16(low, high, p, lanes)) {
        return false;
    }
    PacketBest16 best = noHitYet16();
    for (int i = 0; i < candidates.count && lanes != 0; ++i) {
        keepTriangle16(best, bvh.triangleBlocks[candidates.block[i]], candidates.lane[i], p, lanes);
    }
    writeBest(halfOf(best, 0), halfLanes(lanes, 0), lowHits);
    writeBest(halfOf(best, 1), halfLanes(lanes, 1), highHits);
    return true;
}

RAYLAB_AVX512 bool anyHitCandidates16(const Bvh& bvh, const FrustumCandidates& candidates,
                                      const RayPacket& low, const RayPacket& high,
                                      unsigned& occluded) {
    PacketRays16 p;
    unsigned lanes = 0;
    if (!makeSharedPacket16(low, high, p, lanes)) {
        return false;
    }
    unsigned open = lanes;
    for (int i = 0; i < candidates.count && open != 0; ++i) {
        open &= ~hitLanes16(bvh.triangleBlocks[candidates.block[i]], candidates.lane[i], p, open);
    }
    occluded = lanes & ~open;
    return true;
}

} // namespace raylab

#else // not x86: bvhPacket16Supported() is false, so these are never called.

namespace raylab {
unsigned closestHitPacket16(const Bvh&, const RayPacket&, const RayPacket&, HitPacket&,
                            HitPacket&) {
    return 0;
}
unsigned anyHitPacket16(const Bvh&, const RayPacket&, const RayPacket&, unsigned& occluded,
                        LastOccluder*) {
    occluded = 0;
    return 0;
}
bool closestHitCandidates16(const Bvh&, const FrustumCandidates&, const RayPacket&,
                            const RayPacket&, HitPacket&, HitPacket&) {
    return false;
}
bool anyHitCandidates16(const Bvh&, const FrustumCandidates&, const RayPacket&, const RayPacket&,
                        unsigned&) {
    return false;
}
} // namespace raylab

#endif
