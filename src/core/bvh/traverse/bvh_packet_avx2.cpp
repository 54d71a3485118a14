// AVX2 packet traversal of the 8-wide BVH: the 8 lanes of a register are 8 rays. For coherent
// rays a node costs little more than it costs one ray, as for the 16-ray packets
// (bvh_packet16_avx512.cpp):
// - the packet's frustum (bvh_packet_frustum.h) tests all 8 children at once and leaves out every
//   child no lane can enter; when it leaves out all 8, the visit ends there;
// - the first active lane's own ray tests the 8 children; a candidate it enters is taken with
//   every active lane (a superset of the lanes that enter it) and the frustum's entry distance;
// - only the other candidates are tested lane by lane (hitChild);
// - in a leaf, the frustum leaves out the triangles whose (padded) bounding box no lane can
//   enter, and each other triangle is tested against the active lanes, or, where fewer rays
//   reach a block than it has such triangles, each ray against the block's 8 triangles at once
//   (the single-ray traversal's test).
// Any hit with a LastOccluder (bvh_packet.h) first tests the triangle that occluded a lane of an
// earlier packet against all lanes (before the frustum is made, which a packet it answers whole
// never needs), then the other triangles of its block against the lanes left open, traverses
// only for the lanes still open, and remembers a triangle that a lane hits.
// Keeping a box or a triangle for a lane that misses it costs time, never an answer.
//
// Exactness, lane by lane: the triangle test is intersectTriangle (triangle_intersection.cpp)
// operation for operation (core builds with -ffp-contract=off), valid because all lanes share
// the ray permutation kx, ky, kz (bvh_packet.cpp sends the others to the single-ray path); lanes
// with an edge function of exactly zero go to intersectTriangle itself. A lane keeps the minimum
// of (t, triangle index) over the triangles it hits, and only drops boxes that start beyond its
// own closest hit, as the single-ray traversal does, so the visiting order (the packet's) does
// not change its answer; every culling test above keeps a superset of the lanes' own slab tests.

#include "bvh/traverse/bvh_packet_traverse.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/traverse/bvh_packet_parts.h"

namespace raylab {

namespace {

using namespace packet_lanes;

struct PacketEntry {
    __m256 tNear; // per lane, at most the lane's entry distance
    uint32_t ref;
    unsigned lanes; // a superset of the lanes whose ray enters the box
};

// The children of a node that some lane of `active` may enter (the header comment says how),
// each prefetched (prefetchChild), sorted nearest last by the entry distance of their first lane
// when `ordered` (closest hit), else in slot order (any hit: the sort costs more than it saves
// there; callgrind on the shadow packets: box -3.6%, Sponza -3.6%, dragon -8.7% instructions
// without it). Returns how many.
template <bool ordered>
RAYLAB_AVX2 inline int hitChildren(const Bvh& bvh, const BvhWideNode& node, const PacketRays& p,
                                   const PacketCulling& cull, __m256 limit, unsigned active,
                                   PacketEntry* out) {
    int n = 0;
    float key[kWideLanes];
    unsigned candidates = 0xffu, firstLane = 0;
    alignas(32) float frustumNear[kWideLanes];
    if (cull.frustum.valid) {
        candidates = frustumChildren(node, cull.frustum, cull.limitMax, cull, __builtin_ctz(active),
                                     frustumNear, firstLane);
        if (candidates == 0) {
            return 0; // no lane enters a child
        }
    }
    for (unsigned m = candidates; m != 0; m &= m - 1) {
        const int c = __builtin_ctz(m);
        if (node.child[c] == kWideEmpty) {
            continue;
        }
        __m256 tNear;
        unsigned lanes;
        if ((firstLane >> c) & 1u) {
            tNear = _mm256_set1_ps(frustumNear[c]);
            lanes = active;
        } else {
            lanes = hitChild(node, c, p, limit, tNear) & active;
        }
        if (lanes == 0) {
            continue;
        }
        prefetchChild(bvh, node.child[c]);
        if constexpr (!ordered) {
            out[n++] = PacketEntry{tNear, node.child[c], lanes};
            continue;
        }
        alignas(32) float t[kWideLanes];
        _mm256_store_ps(t, tNear);
        const float k = t[__builtin_ctz(lanes)];
        int i = n++;
        for (; i > 0 && key[i - 1] < k; --i) {
            key[i] = key[i - 1];
            out[i] = out[i - 1];
        }
        key[i] = k;
        out[i] = PacketEntry{tNear, node.child[c], lanes};
    }
    return n;
}

// Goes on with the last of a node's n > 0 hit children (the nearest, when they are sorted) and
// its lanes, and pushes the others on the stack.
RAYLAB_AVX2 inline void descend(const PacketEntry* children, int n, PacketEntry* stack, int& size,
                                uint32_t& ref, unsigned& active) {
    for (int i = 0; i < n - 1; ++i) {
        stack[size++] = children[i];
    }
    ref = children[n - 1].ref;
    active = children[n - 1].lanes;
}

// The lanes of p that the other triangles of last's block (one of bvh's) occlude, given `found`,
// those its triangle occludes: while some lane is open, each other triangle of the block that an
// open lane may hit (frustumTriangles) against the open lanes. Neighbouring shadow rays that
// last's triangle leaves open are often blocked by a triangle next to it. last's slot moves to a
// triangle that occludes a lane. Returns found with those lanes added.
RAYLAB_AVX2 inline unsigned lastBlockLanes(const Bvh& bvh, const PacketRays& p,
                                           const PacketCulling& cull, const RayPacket& rays,
                                           LastOccluder& last, unsigned found) {
    const BvhTriangleBlock& block = bvh.triangleBlocks[last.block];
    const int slot = last.slot & (kWideLanes - 1);
    const unsigned others = distinctTriangles(block) & ~(1u << slot) &
                            frustumTriangles(block, bvh.boxPad, cull.frustum, cull.limitMax);
    for (unsigned m = others; m != 0 && found != p.lanes; m &= m - 1) {
        const int tri = __builtin_ctz(m);
        const unsigned hit = hitLanes(block, tri, p, rays, p.lanes & ~found);
        if (hit != 0) {
            found |= hit;
            last.slot = tri;
        }
    }
    return found;
}

} // namespace

RAYLAB_AVX2 unsigned closestHitPacket(const Bvh& bvh, const RayPacket& rays, HitPacket& hits) {
    PacketRays p;
    makePacket(rays, p);
    const unsigned lanes = p.lanes;
    if (lanes == 0) {
        hits.clear();
        return p.others;
    }
    PacketCulling cull;
    makeCulling(p, cull);
    PacketBest best = noHitYet();
    __m256 limit = p.tMax; // per lane: min(tMax, best.t)
    const __m256 roundUp = _mm256_set1_ps(kBoxRoundUp);
    PacketEntry stack[kWideStackSize];
    int size = 0;
    uint32_t ref = 0;
    unsigned active = lanes;
    for (;;) {
        if (!isLeaf(ref)) {
            PacketEntry children[kWideLanes];
            const int n =
                hitChildren<true>(bvh, bvh.wideNodes[ref], p, cull, limit, active, children);
            if (n > 0) {
                descend(children, n, stack, size, ref, active);
                continue;
            }
        } else {
            unsigned found = 0;
            testLeaf(bvh, ref, p, cull, rays, &best, active, found, nullptr);
            limit = _mm256_min_ps(p.tMax, best.t);
            setLimits(p, limit, cull);
        }
        // Next: the nearest pending entry that some lane may still find a closer hit in.
        for (;;) {
            if (size == 0) {
                writeBest(best, lanes, hits);
                return p.others;
            }
            const PacketEntry& e = stack[--size];
            const unsigned open =
                e.lanes & static_cast<unsigned>(_mm256_movemask_ps(
                              _mm256_cmp_ps(e.tNear, _mm256_mul_ps(limit, roundUp), _CMP_LE_OQ)));
            if (open != 0) {
                ref = e.ref;
                active = open;
                break;
            }
        }
    }
}

RAYLAB_AVX2 unsigned anyHitPacket(const Bvh& bvh, const RayPacket& rays, unsigned& occluded,
                                  LastOccluder* last) {
    PacketRays p;
    makePacket(rays, p);
    occluded = 0;
    const unsigned lanes = p.lanes;
    if (lanes == 0) {
        return p.others;
    }
    unsigned found = 0; // lanes with a hit
    const bool remembered = last != nullptr && last->block < bvh.triangleBlocks.size();
    if (remembered) {
        // Before the frustum is made: a packet whose every lane this triangle occludes (half of
        // Sponza's shadow packets) needs none.
        found = hitLanes(bvh.triangleBlocks[last->block], last->slot & (kWideLanes - 1), p, rays,
                         lanes);
        if (found == lanes) {
            occluded = found;
            return p.others;
        }
    }
    PacketCulling cull;
    makeCulling(p, cull);
    if (remembered) {
        found = lastBlockLanes(bvh, p, cull, rays, *last, found);
        if (found == lanes) {
            occluded = found;
            return p.others;
        }
    }
    PacketEntry stack[kWideStackSize];
    int size = 0;
    uint32_t ref = 0;
    unsigned active = lanes & ~found;
    for (;;) {
        if (!isLeaf(ref)) {
            PacketEntry children[kWideLanes];
            const int n =
                hitChildren<false>(bvh, bvh.wideNodes[ref], p, cull, p.tMax, active, children);
            if (n > 0) {
                descend(children, n, stack, size, ref, active);
                continue;
            }
        } else {
            testLeaf(bvh, ref, p, cull, rays, nullptr, active, found, last);
            if (found == lanes) {
                break;
            }
        }
        // Next: a pending entry with a lane still unanswered.
        for (;;) {
            if (size == 0) {
                active = 0;
                break;
            }
            const PacketEntry& e = stack[--size];
            if ((e.lanes & ~found) != 0) {
                ref = e.ref;
                active = e.lanes & ~found;
                break;
            }
        }
        if (active == 0) {
            break;
        }
    }
    occluded = found & lanes;
    return p.others;
}

} // namespace raylab

#else // not x86: buildBvh never builds the wide form, so these are never called.

namespace raylab {
unsigned closestHitPacket(const Bvh&, const RayPacket&, HitPacket&) { return 0; }
unsigned anyHitPacket(const Bvh&, const RayPacket&, unsigned&, LastOccluder*) { return 0; }
} // namespace raylab

#endif
