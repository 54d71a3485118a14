// AVX2 packet traversal of the 8-wide BVH: the 8 lanes of a register are 8 rays. A node tests
// each child's box against all rays and descends when any active ray hits it; a leaf tests each
// triangle against all rays at once.
//
// Exactness, lane by lane: the triangle test is intersectTriangle (triangle_intersection.cpp)
// operation for operation (core builds with -ffp-contract=off), valid because all lanes share
// the ray permutation kx, ky, kz (bvh_packet.cpp sends the others to the single-ray path); lanes
// with an edge function of exactly zero go to intersectTriangle itself. A lane keeps the minimum
// of (t, triangle index) over the triangles it hits, and only drops boxes that start beyond its
// own closest hit, as the single-ray traversal does, so the visiting order (the packet's) does
// not change its answer.

#include "bvh/traverse/bvh_packet_traverse.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/build/bvh_collapse.h"
#include "bvh/traverse/bvh_packet_lanes.h"

namespace raylab {

namespace {

using namespace packet_lanes;

struct PacketEntry {
    __m256 tNear; // per lane
    uint32_t ref;
    unsigned lanes; // lanes whose ray entered the box
};

// The children of a node that some lane of `active` hits, each prefetched (prefetchChild), sorted
// nearest last by the entry distance of their first hitting lane when `ordered` (closest hit), else
// in slot order (any hit: the sort costs more than it saves there; callgrind on the shadow packets:
// box -3.6%, Sponza -3.6%, dragon -8.7% instructions without it). Returns how many.
template <bool ordered>
RAYLAB_AVX2 inline int hitChildren(const Bvh& bvh, const BvhWideNode& node, const PacketRays& p,
                                   __m256 limit, unsigned active, PacketEntry* out) {
    int n = 0;
    float key[kWideLanes];
    for (int c = 0; c < kWideLanes; ++c) {
        if (node.child[c] == kWideEmpty) {
            continue;
        }
        __m256 tNear;
        const unsigned lanes = hitChild(node, c, p, limit, tNear) & active;
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

} // namespace

RAYLAB_AVX2 unsigned closestHitPacket(const Bvh& bvh, const RayPacket& rays, HitPacket& hits) {
    PacketRays p;
    makePacket(rays, p);
    const unsigned lanes = p.lanes;
    if (lanes == 0) {
        hits.clear();
        return p.others;
    }
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
            const int n = hitChildren<true>(bvh, bvh.wideNodes[ref], p, limit, active, children);
            if (n > 0) {
                descend(children, n, stack, size, ref, active);
                continue;
            }
        } else {
            const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
            for (uint32_t b = blockCount(ref); b > 0; --b, ++block) {
                for (int tri = 0; tri < kWideLanes; ++tri) {
                    if (repeatsFirst(*block, tri)) {
                        continue;
                    }
                    keepTriangle(best, *block, tri, p, rays, active);
                }
            }
            limit = _mm256_min_ps(p.tMax, best.t);
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

RAYLAB_AVX2 unsigned anyHitPacket(const Bvh& bvh, const RayPacket& rays, unsigned& occluded) {
    PacketRays p;
    makePacket(rays, p);
    occluded = 0;
    const unsigned lanes = p.lanes;
    if (lanes == 0) {
        return p.others;
    }
    unsigned found = 0; // lanes with a hit
    PacketEntry stack[kWideStackSize];
    int size = 0;
    uint32_t ref = 0;
    unsigned active = lanes;
    for (;;) {
        if (!isLeaf(ref)) {
            PacketEntry children[kWideLanes];
            const int n = hitChildren<false>(bvh, bvh.wideNodes[ref], p, p.tMax, active, children);
            if (n > 0) {
                descend(children, n, stack, size, ref, active);
                continue;
            }
        } else {
            const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
            for (uint32_t b = blockCount(ref); b > 0 && active != 0; --b, ++block) {
                for (int tri = 0; tri < kWideLanes && active != 0; ++tri) {
                    if (repeatsFirst(*block, tri)) {
                        continue;
                    }
                    const unsigned hit = hitLanes(*block, tri, p, rays, active);
                    found |= hit;
                    active &= ~hit;
                }
            }
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
unsigned anyHitPacket(const Bvh&, const RayPacket&, unsigned&) { return 0; }
} // namespace raylab

#endif
