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
// against all 16 lanes, then the other triangles of its block against the lanes left open,
// traverses only for the lanes still open, and remembers a triangle that a lane hits.
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

#include "avx512_warnings.h" // first: before any intrinsics header
#include "bvh/traverse/bvh_packet16_traverse.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/traverse/bvh_packet16_parts.h"

namespace raylab {

namespace {

using namespace packet16_lanes;

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

// The lanes of p that the triangles of last's block (one of bvh's) occlude: last's triangle
// against all lanes, then, while some are open, each other triangle of its block that an open lane
// may hit (frustumTriangles) against the open lanes. Neighbouring shadow rays that last's triangle
// leaves open are often blocked by a triangle next to it. last's slot moves to a triangle that
// occludes a lane.
RAYLAB_AVX512 inline unsigned lastOccluderLanes(const Bvh& bvh, const Packet16& p, float tMaxMax,
                                                LastOccluder& last) {
    const BvhTriangleBlock& block = bvh.triangleBlocks[last.block];
    const int slot = last.slot & (kWideLanes - 1);
    unsigned found = hitLanes16(block, slot, p.rays, p.lanes);
    if (found == p.lanes) {
        return found;
    }
    const unsigned others = distinctTriangles(block) & ~(1u << slot) &
                            frustumTriangles(block, bvh.boxPad, p.frustum, tMaxMax);
    for (unsigned m = others; m != 0 && found != p.lanes; m &= m - 1) {
        const int tri = __builtin_ctz(m);
        const unsigned hit = hitLanes16(block, tri, p.rays, p.lanes & ~found);
        if (hit != 0) {
            found |= hit;
            last.slot = tri;
        }
    }
    return found;
}

RAYLAB_AVX512 unsigned anyHit16Avx512(const Bvh& bvh, const Packet16& p, LastOccluder* last) {
    const float tMaxMax = _mm512_mask_reduce_max_ps(static_cast<__mmask16>(p.lanes), p.rays.tMax);
    unsigned found = 0; // lanes with a hit
    if (last != nullptr && last->block < bvh.triangleBlocks.size()) {
        found = lastOccluderLanes(bvh, p, tMaxMax, *last);
        if (found == p.lanes) {
            return found;
        }
    }
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
