// Closest hits of 64 rays in one walk of the 8-wide BVH with AVX2: eight 8-ray packets
// (makePacket) that share one frustum, as the AVX-512 walk shares one among four 16-ray packets
// (bvh_packet64_avx512.cpp, whose steps these are on 8 lanes). For a block of 8 x 8 camera rays a
// node visit then serves 64 rays where the 8-ray traversal (bvh_packet_avx2.cpp) serves 8:
// - the frustum of the 64 rays (the packets' frustums joined) tests all 8 children at once;
//   when it leaves out all 8, the visit ends there;
// - the first active lane's own ray tests the 8 children; a candidate it enters is taken with
//   every active lane and the frustum's entry distance;
// - the other candidates are tested against each packet with active lanes (hitChild); the child
//   is taken with the lanes that enter it and the least of their entry distances;
// - in a leaf each packet with active lanes is tested as the 8-ray traversal tests it
//   (testBlock), with its own, narrower frustum, block by block, each block's triangle boxes made
//   once for all the packets;
// - a pending child is visited again only for the lanes whose closest hit so far lies beyond its
//   entry distance.
// Each culling test keeps a superset of the lanes' own slab tests, and every triangle test is the
// 8-ray packets', so each lane's answer is the single ray's bit for bit. Each packet keeps its own
// ray permutation; its lanes of another permutation go to the single-ray path, as in the 8-ray
// packets.

#include "bvh/traverse/bvh_packet_traverse.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/traverse/bvh_packet64_entry.h"
#include "bvh/traverse/bvh_packet_parts.h"

#include <algorithm>

namespace raylab {

namespace {

using namespace packet_lanes;

// Eight packets of 8 rays; lane 8 k + i of the 64 is lane i of packet k.
constexpr int kPackets = 8;

// Packet k's 8 lanes of a 64-lane mask.
inline unsigned packetLanes(uint64_t lanes, int k) {
    return static_cast<unsigned>(lanes >> (kPacketSize * k)) & 0xffu;
}

inline uint64_t asLanes64(unsigned lanes, int k) {
    return static_cast<uint64_t>(lanes) << (kPacketSize * k);
}

struct EightPackets {
    const RayPacket* rays = nullptr; // for the exact fallback of the triangle tests
    PacketRays packet[kPackets];     // a packet without lanes has lanes == 0
    PacketCulling cull[kPackets];    // each packet's own frustum, lane constants and limits
    PacketBest best[kPackets];       // the closest hits so far
    __m256 limit[kPackets];          // per lane: min(tMax, best t)
    Frustum frustum;                 // of every packet's lanes
    float limitMax = -kInfinity;     // the largest limit of all lanes (with a valid frustum)
    uint64_t lanes = 0;
    uint32_t leaves = 0;          // leaves entered (CameraWalks)
    uint32_t packetLeafTests = 0; // packets tested in them
};

// The frustum of the packets' lanes (joinFrustums of each packet's, makeFrustum8).
RAYLAB_AVX2 inline Frustum joinFrustums(const EightPackets& p) {
    const Frustum* frustums[kPackets];
    for (int k = 0; k < kPackets; ++k) {
        frustums[k] = p.packet[k].lanes != 0 ? &p.cull[k].frustum : nullptr;
    }
    return joinFrustums(frustums, kPackets);
}

// Sets the limits of the packets with lanes in `changed` from their closest hits, and the largest
// of all.
RAYLAB_AVX2 inline void updateLimits(uint64_t changed, EightPackets& p) {
    p.limitMax = -kInfinity;
    for (int k = 0; k < kPackets; ++k) {
        const PacketRays& q = p.packet[k];
        if (q.lanes == 0) {
            continue;
        }
        if (packetLanes(changed, k) != 0) {
            p.limit[k] = _mm256_min_ps(q.tMax, p.best[k].t);
            setLimits(q, p.limit[k], p.cull[k]);
        }
        p.limitMax = std::max(p.limitMax, p.cull[k].limitMax);
    }
}

// The children of a node that some lane of `active` may enter (the header comment says how),
// each prefetched (prefetchChild), written to out[0, n) nearest last by their tNear. Returns n.
RAYLAB_AVX2 inline int hitChildren64(const Bvh& bvh, const BvhWideNode& node, const EightPackets& p,
                                     uint64_t active, Entry64* out) {
    unsigned candidates = 0xffu, firstLane = 0;
    alignas(32) float frustumNear[kWideLanes];
    if (p.frustum.valid) {
        const int l = __builtin_ctzll(active);
        candidates = frustumChildren(node, p.frustum, p.limitMax, p.cull[l / kPacketSize],
                                     l % kPacketSize, frustumNear, firstLane);
        if (candidates == 0) {
            return 0; // no lane enters a child
        }
    }
    int n = 0;
    for (unsigned m = candidates; m != 0; m &= m - 1) {
        const int c = __builtin_ctz(m);
        if (node.child[c] == kWideEmpty) {
            continue;
        }
        float tNear = kInfinity;
        uint64_t lanes = 0;
        if ((firstLane >> c) & 1u) {
            tNear = frustumNear[c];
            lanes = active;
        } else {
            for (int k = 0; k < kPackets; ++k) {
                const unsigned a = packetLanes(active, k);
                if (a == 0) {
                    continue;
                }
                __m256 t;
                const unsigned hit = hitChild(node, c, p.packet[k], p.limit[k], t) & a;
                if (hit != 0) {
                    lanes |= asLanes64(hit, k);
                    tNear = std::min(tNear, laneMin(t, hit));
                }
            }
            if (lanes == 0) {
                continue;
            }
        }
        prefetchChild(bvh, node.child[c]);
        n = insertNearestLast(out, n, Entry64{tNear, node.child[c], lanes});
    }
    return n;
}

// Tests the triangles of leaf `ref` against the lanes of `active`, each packet as the 8-ray
// traversal tests it (testBlock, with its own frustum), and keeps the lanes' closest hits in
// p.best. Block by block, so that a block's triangle boxes are made once for all the packets that
// test it (six a leaf on Sponza): each packet still tests the leaf's blocks in their order, so its
// answers are testLeaf's (PERFORMANCE.md, "A leaf's triangle boxes made once for its packets").
RAYLAB_AVX2 inline void testLeaf64(const Bvh& bvh, uint32_t ref, uint64_t active, EightPackets& p) {
    ++p.leaves;
    bool frustumTests = false; // some packet tests triangle boxes against its frustum
    for (int k = 0; k < kPackets; ++k) {
        const unsigned lanes = packetLanes(active, k);
        p.packetLeafTests += lanes != 0 ? 1 : 0;
        frustumTests |= (lanes & (lanes - 1)) != 0 && p.cull[k].frustum.valid;
    }
    const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
    for (uint32_t b = blockCount(ref); b > 0; --b, ++block) {
        TriangleBounds bounds;
        if (frustumTests) {
            bounds = triangleBounds(*block, bvh.boxPad);
        }
        for (int k = 0; k < kPackets; ++k) {
            unsigned lanes = packetLanes(active, k);
            if (lanes != 0) {
                unsigned found = 0; // any hit only
                testBlock(bvh, block, frustumTests ? &bounds : nullptr, p.packet[k], p.cull[k],
                          p.rays[k], &p.best[k], lanes, found, nullptr);
            }
        }
    }
}

// Traces p (lanes != 0) and writes every lane of hits[0, 8).
RAYLAB_AVX2 void walk64(const Bvh& bvh, EightPackets& p, HitPacket* hits) {
    const __m256 roundUp = _mm256_set1_ps(kBoxRoundUp);
    Entry64 stack[kWideStackSize + 1]; // + 1: a node's children are written above the top
    int size = 0;
    uint32_t ref = 0;
    uint64_t active = p.lanes;
    for (;;) {
        if (!isLeaf(ref)) {
            const int n = hitChildren64(bvh, bvh.wideNodes[ref], p, active, stack + size);
            if (n > 0) {
                size += n - 1;
                ref = stack[size].ref;
                active = stack[size].lanes;
                continue;
            }
        } else {
            testLeaf64(bvh, ref, active, p);
            updateLimits(active, p);
        }
        // Next: the nearest pending entry that some lane may still find a closer hit in.
        for (;;) {
            if (size == 0) {
                for (int k = 0; k < kPackets; ++k) {
                    writeBest(p.best[k], p.packet[k].lanes, hits[k]);
                }
                return;
            }
            const Entry64& e = stack[--size];
            const __m256 tNear = _mm256_set1_ps(e.tNear);
            uint64_t open = 0;
            for (int k = 0; k < kPackets; ++k) {
                if (const unsigned a = packetLanes(e.lanes, k); a != 0) {
                    const __m256 near =
                        _mm256_cmp_ps(tNear, _mm256_mul_ps(p.limit[k], roundUp), _CMP_LE_OQ);
                    open |= asLanes64(a & static_cast<unsigned>(_mm256_movemask_ps(near)), k);
                }
            }
            if (open != 0) {
                ref = e.ref;
                active = open;
                break;
            }
        }
    }
}

} // namespace

RAYLAB_AVX2 uint64_t closestHitEightPackets(const Bvh& bvh, const RayPacket* rays, HitPacket* hits,
                                            CameraWalks* walks) {
    EightPackets p;
    p.rays = rays;
    uint64_t single = 0;
    for (int k = 0; k < kPackets; ++k) {
        PacketRays& q = p.packet[k];
        makePacket(rays[k], q);
        single |= asLanes64(q.others, k);
        p.best[k] = noHitYet();
        p.limit[k] = q.tMax;
        if (q.lanes != 0) {
            makeCulling(q, p.cull[k]);
            p.lanes |= asLanes64(q.lanes, k);
        }
    }
    if (p.lanes == 0) {
        for (int k = 0; k < kPackets; ++k) {
            hits[k].clear();
        }
        return single;
    }
    p.frustum = joinFrustums(p);
    updateLimits(0, p);
    walk64(bvh, p, hits);
    if (walks != nullptr) {
        walks->leaves += p.leaves;
        walks->packetLeafTests += p.packetLeafTests;
    }
    return single;
}

} // namespace raylab

#else // not x86: buildBvh never builds the wide form, so this is never called.

namespace raylab {
uint64_t closestHitEightPackets(const Bvh&, const RayPacket*, HitPacket*, CameraWalks*) {
    return 0;
}
} // namespace raylab

#endif
