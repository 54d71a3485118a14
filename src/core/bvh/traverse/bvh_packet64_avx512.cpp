// Closest hits of 64 rays in one walk of the 8-wide BVH (AVX-512F): four 16-ray packets
// (makePacket16, each two RayPackets) that share one frustum. For a block of 8 x 8 camera rays
// (four 4 x 4 tiles) a node visit then serves 64 rays where the 16-ray traversal
// (bvh_packet16_avx512.cpp) serves 16, for about the same fixed cost; the wider frustum keeps a
// few more children:
// - the frustum of the 64 rays (the four packets' frustums joined) tests all 8 children at once;
//   when it leaves out all 8, the visit ends there;
// - the first active lane's own ray tests the 8 children; a candidate it enters is taken with
//   every active lane and the frustum's entry distance;
// - the other candidates are tested against each packet with active lanes (hitChild16); the
//   child is taken with the lanes that enter it and the least of their entry distances;
// - in a leaf each packet with active lanes is tested as the 16-ray traversal tests it
//   (testLeaf), with its own, narrower frustum;
// - a pending child is visited again only for the lanes whose closest hit so far lies beyond its
//   entry distance.
// Each culling test keeps a superset of the lanes' own slab tests, and every triangle test is the
// 16-ray packets', so each lane's answer is the single ray's bit for bit. A pair of RayPackets
// whose halves have different ray permutations goes its own way (two 8-lane packets), and lanes
// of other permutations within a half to the single-ray path, as in the 16-ray packets.

#include "avx512_warnings.h" // first: before any intrinsics header
#include "bvh/traverse/bvh_packet16_traverse.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/traverse/bvh_packet16_parts.h"
#include "bvh/traverse/bvh_packet64_entry.h"

#include <algorithm>

namespace raylab {

namespace {

using namespace packet16_lanes;

// Four packets of 16 rays; lane 16 w + l of the 64 is lane l of packet w.
constexpr int kPackets = 4;

struct Packet64 {
    Packet16 packet[kPackets]; // a packet traced on its own, or without lanes, has lanes == 0
    Frustum frustum;           // of every packet's lanes
    uint64_t lanes = 0;
};

// Packet w's 16 lanes of a 64-lane mask.
inline unsigned packetLanes(uint64_t lanes, int w) {
    return static_cast<unsigned>(lanes >> (kPacket16Size * w)) & 0xffffu;
}

inline uint64_t asLanes64(unsigned lanes, int w) {
    return static_cast<uint64_t>(lanes) << (kPacket16Size * w);
}

// The frustum of the packets' lanes (joinFrustums of each packet's, makeFrustum).
RAYLAB_AVX512 inline Frustum joinFrustums(const Packet64& p) {
    const Frustum* frustums[kPackets];
    for (int w = 0; w < kPackets; ++w) {
        frustums[w] = p.packet[w].lanes != 0 ? &p.packet[w].frustum : nullptr;
    }
    return joinFrustums(frustums, kPackets);
}

// The closest hits so far and what they bound: per packet, each lane's limit min(tMax, best t)
// and the largest of them; as floats per lane for laneChildren; the largest of all.
struct Limits64 {
    PacketBest16 best[kPackets];
    __m512 limit[kPackets];
    float packetMax[kPackets];
    alignas(64) float lane[kPacket16Size * kPackets];
    float max = -kInfinity;
};

// Sets limits from the closest hits of the packets with lanes in `changed`.
RAYLAB_AVX512 inline void updateLimits(const Packet64& p, uint64_t changed, Limits64& s) {
    s.max = -kInfinity;
    for (int w = 0; w < kPackets; ++w) {
        const Packet16& q = p.packet[w];
        if (packetLanes(changed, w) != 0) {
            s.limit[w] = _mm512_min_ps(q.rays.tMax, s.best[w].t);
            s.packetMax[w] = _mm512_mask_reduce_max_ps(static_cast<__mmask16>(q.lanes), s.limit[w]);
            _mm512_store_ps(s.lane + kPacket16Size * w, s.limit[w]);
        }
        s.max = std::max(s.max, s.packetMax[w]);
    }
}

// The limits of p's lanes before any hit: their tMax.
RAYLAB_AVX512 inline Limits64 startLimits(const Packet64& p) {
    Limits64 s;
    for (int w = 0; w < kPackets; ++w) {
        s.best[w] = noHitYet16();
        s.limit[w] = _mm512_set1_ps(kInfinity);
        s.packetMax[w] = -kInfinity;
    }
    updateLimits(p, p.lanes, s);
    return s;
}

// The children of a node that some lane of `active` may enter (the header comment says how),
// each prefetched (prefetchChild), written to out[0, n) nearest last by their tNear. Returns n.
RAYLAB_AVX512 inline int hitChildren64(const Bvh& bvh, const BvhWideNode& node, const Packet64& p,
                                       const Limits64& s, uint64_t active, Entry64* out) {
    unsigned candidates = 0xffu, firstLane = 0;
    alignas(32) float frustumNear[kWideLanes];
    if (p.frustum.valid) {
        __m256 tNear;
        candidates = frustumBoxes(&node.lower[0][0], p.frustum, s.max, tNear);
        if (candidates == 0) {
            return 0; // no lane enters a child
        }
        _mm256_store_ps(frustumNear, tNear);
        const int l = __builtin_ctzll(active);
        firstLane = candidates & laneChildren(node, p.packet[l / kPacket16Size].scalars,
                                              l % kPacket16Size, s.lane[l]);
    }
    int n = 0;
    for (unsigned m = candidates; m != 0; m &= m - 1) {
        const int c = __builtin_ctz(m);
        if (node.child[c] == kWideEmpty) {
            continue;
        }
        float tNear = 0.0f;
        uint64_t lanes = 0;
        if ((firstLane >> c) & 1u) {
            tNear = frustumNear[c];
            lanes = active;
        } else {
            __m512 least = _mm512_set1_ps(kInfinity);
            for (int w = 0; w < kPackets; ++w) {
                const unsigned a = packetLanes(active, w);
                if (a == 0) {
                    continue;
                }
                __m512 t;
                const unsigned hit = hitChild16(node, c, p.packet[w].rays, s.limit[w], t) & a;
                lanes |= asLanes64(hit, w);
                least = _mm512_mask_min_ps(least, static_cast<__mmask16>(hit), least, t);
            }
            if (lanes == 0) {
                continue;
            }
            tNear = _mm512_reduce_min_ps(least);
        }
        prefetchChild(bvh, node.child[c]);
        n = insertNearestLast(out, n, Entry64{tNear, node.child[c], lanes});
    }
    return n;
}

// Tests the triangles of leaf `ref` against the lanes of `active`, packet by packet, each as the
// 16-ray traversal does (testLeaf), and keeps the lanes' closest hits in s.best.
RAYLAB_AVX512 inline void testLeaf64(const Bvh& bvh, uint32_t ref, const Packet64& p,
                                     uint64_t active, Limits64& s) {
    for (int w = 0; w < kPackets; ++w) {
        unsigned lanes = packetLanes(active, w);
        if (lanes != 0) {
            unsigned found = 0; // any hit only
            testLeaf<true>(bvh, ref, p.packet[w], s.packetMax[w], &s.best[w], lanes, found,
                           nullptr);
        }
    }
}

// Traces p (lanes != 0) and writes the hits of the packets in `traced` (bit w: hits[2w, 2w + 2)).
RAYLAB_AVX512 void closestHit64Avx512(const Bvh& bvh, const Packet64& p, unsigned traced,
                                      HitPacket* hits) {
    Limits64 s = startLimits(p);
    const __m512 roundUp = _mm512_set1_ps(kBoxRoundUp);
    Entry64 stack[kWideStackSize + 1]; // + 1: a node's children are written above the top
    int size = 0;
    uint32_t ref = 0;
    uint64_t active = p.lanes;
    for (;;) {
        if (!isLeaf(ref)) {
            const int n = hitChildren64(bvh, bvh.wideNodes[ref], p, s, active, stack + size);
            if (n > 0) {
                size += n - 1;
                ref = stack[size].ref;
                active = stack[size].lanes;
                continue;
            }
        } else {
            testLeaf64(bvh, ref, p, active, s);
            updateLimits(p, active, s);
        }
        // Next: the nearest pending entry that some lane may still find a closer hit in.
        for (;;) {
            if (size == 0) {
                for (int w = 0; w < kPackets; ++w) {
                    if ((traced >> w) & 1u) {
                        for (int h = 0; h < 2; ++h) {
                            writeBest(halfOf(s.best[w], h), halfLanes(p.packet[w].lanes, h),
                                      hits[2 * w + h]);
                        }
                    }
                }
                return;
            }
            const Entry64& e = stack[--size];
            const __m512 tNear = _mm512_set1_ps(e.tNear);
            uint64_t open = 0;
            for (int w = 0; w < kPackets; ++w) {
                if (const unsigned a = packetLanes(e.lanes, w); a != 0) {
                    open |=
                        asLanes64(a & _mm512_cmp_ps_mask(tNear, _mm512_mul_ps(s.limit[w], roundUp),
                                                         _CMP_LE_OQ),
                                  w);
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

RAYLAB_AVX512 uint64_t closestHitPacket64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits) {
    Packet64 p;
    uint64_t single = 0;
    unsigned traced = 0; // packets traced in the 64-ray walk
    for (int w = 0; w < kPackets; ++w) {
        Packet16& q = p.packet[w];
        if (!makePacket16(rays[2 * w], rays[2 * w + 1], q)) {
            single |= asLanes64(closestHitPacket(bvh, rays[2 * w], hits[2 * w]) |
                                    closestHitPacket(bvh, rays[2 * w + 1], hits[2 * w + 1])
                                        << kPacketSize,
                                w);
            q.lanes = 0;
            continue;
        }
        traced |= 1u << w;
        single |= asLanes64(q.others, w);
        p.lanes |= asLanes64(q.lanes, w);
    }
    if (p.lanes == 0) {
        for (int w = 0; w < kPackets; ++w) {
            if ((traced >> w) & 1u) {
                hits[2 * w].clear();
                hits[2 * w + 1].clear();
            }
        }
        return single;
    }
    p.frustum = joinFrustums(p);
    closestHit64Avx512(bvh, p, traced, hits);
    return single;
}

} // namespace raylab

#else // not x86: bvhPacket16Supported() is false, so this is never called.

namespace raylab {
uint64_t closestHitPacket64(const Bvh&, const RayPacket*, HitPacket*) { return 0; }
} // namespace raylab

#endif
