// AVX2 traversal of the 8-wide BVH: 8 child boxes per node test and 8 triangles per block test.
//
// Only these functions use AVX2 (target attribute), and they only run when the wide BVH was
// built, which buildBvh does only on CPUs with AVX2; the rest of the library stays baseline x86-64.
//
// The 8-lane triangle test is intersectTriangle (triangle_intersection.cpp) operation for
// operation: the same subtractions, products and quotients in the same order, each rounded the
// same way (IEEE single precision, no fused multiply-add: core builds with -ffp-contract=off), so
// t, u and v are bit for bit those of the scalar test. Lanes where an edge function is exactly
// zero, where the scalar test switches to double precision, go to intersectTriangle itself.

#include "bvh/traverse/bvh_wide_traverse.h"
#include "finite.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/build/bvh_collapse.h"
#include "bvh/traverse/bvh_block_ray.h"
#include "bvh/traverse/bvh_box_ray.h"
#include "bvh/traverse/bvh_wide_refs.h"

#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <immintrin.h>
#include <utility>

namespace raylab {

namespace {

// The per-ray constants, broadcast to 8 lanes.
struct WideRay {
    // Box test (BoxRay's): origin, 1/direction for the near bounds and scaled up for the far
    // ones, offsets of the near and far bound in BvhWideNode's floats.
    __m256 origin[3], inverse[3], farInverse[3];
    int nearOffset[3], farOffset[3];
    BlockRay triangles; // the triangle test (WatertightRay's constants)
};

// Fills r for `ray`; false for the rays WatertightRay calls invalid (they hit nothing). The
// permutation and shear are WatertightRay's constructor's, computed the same way (tests check
// that both paths agree bit for bit); the six quotients share one 8-lane division.
RAYLAB_AVX2 inline bool makeWideRay(const Ray& ray, WideRay& r) {
    const glm::vec3& d = ray.direction;
    if (!isFinite(ray.origin) || !isFinite(d) || (d.x == 0.0f && d.y == 0.0f && d.z == 0.0f) ||
        std::isnan(ray.tMin) || std::isnan(ray.tMax)) {
        return false;
    }
    const glm::vec3 a = glm::abs(d);
    const int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.0f) {
        std::swap(kx, ky);
    }
    const int k[3] = {kx, ky, kz};
    // Built in registers (_mm256_set_ps), not through memory: a 256-bit load of values just
    // stored one by one stalls on store forwarding.
    const __m256 numerator = _mm256_set_ps(1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f, d[ky], d[kx]);
    const __m256 denominator = _mm256_set_ps(1.0f, 1.0f, boxDirection(d.z), boxDirection(d.y),
                                             boxDirection(d.x), d[kz], d[kz], d[kz]);
    alignas(32) float q[8];
    _mm256_store_ps(q, _mm256_div_ps(numerator, denominator));
    for (int i = 0; i < 3; ++i) {
        const float inverse = q[3 + i];
        const int nearIsUpper = inverse >= 0.0f ? 0 : 1;
        r.origin[i] = _mm256_set1_ps(ray.origin[i]);
        r.inverse[i] = _mm256_set1_ps(inverse);
        r.farInverse[i] = _mm256_set1_ps(inverse * kBoxRoundUp);
        // lower[i] starts at float i * 8, upper[i] at 24 + i * 8.
        r.nearOffset[i] = nearIsUpper * 24 + i * kWideLanes;
        r.farOffset[i] = (1 - nearIsUpper) * 24 + i * kWideLanes;
        r.triangles.originK[i] = _mm256_set1_ps(ray.origin[k[i]]);
        r.triangles.vertexOffset[i] = k[i] * kWideLanes;
    }
    r.triangles.shearX = _mm256_set1_ps(q[0]);
    r.triangles.shearY = _mm256_set1_ps(q[1]);
    r.triangles.shearZ = _mm256_set1_ps(q[2]);
    r.triangles.tMin = _mm256_set1_ps(ray.tMin);
    r.triangles.tMax = _mm256_set1_ps(ray.tMax);
    return true;
}

// Slab test of the 8 children (bvh_box_ray.h's hitBox, 8 at once). Returns the mask of children
// whose box overlaps (tMin, limit] and their entry distances.
RAYLAB_AVX2 inline int hitChildren(const BvhWideNode& node, const WideRay& r, float limit,
                                   __m256& tNear, __m256& hit) {
    const float* b = &node.lower[0][0];
    __m256 t0[3], t1[3];
    for (int a = 0; a < 3; ++a) {
        t0[a] = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.nearOffset[a]), r.origin[a]),
                              r.inverse[a]);
        t1[a] = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(b + r.farOffset[a]), r.origin[a]),
                              r.farInverse[a]);
    }
    const __m256 tn =
        _mm256_max_ps(_mm256_max_ps(t0[0], t0[1]), _mm256_max_ps(t0[2], r.triangles.tMin));
    const __m256 tf = _mm256_min_ps(_mm256_min_ps(t1[0], t1[1]),
                                    _mm256_min_ps(t1[2], _mm256_set1_ps(limit * kBoxRoundUp)));
    tNear = tn;
    hit = _mm256_cmp_ps(tn, tf, _CMP_LE_OQ);
    return _mm256_movemask_ps(hit);
}

struct StackEntry {
    uint32_t ref;
    float tNear;
};
static_assert(sizeof(StackEntry) == 8, "pushChildren writes entries as pairs of 32-bit lanes");

// One layer of sortDescending: each lane meets `partner` (the lane its shuffle brought) and keeps
// the larger key where bit `lane` of TakeMax is set, the smaller elsewhere.
template <int TakeMax> RAYLAB_AVX2 inline __m256i sortLayer(__m256i keys, __m256i partner) {
    return _mm256_blend_epi32(_mm256_min_epi32(keys, partner), _mm256_max_epi32(keys, partner),
                              TakeMax);
}

// The 8 keys in descending order: a bitonic network of six layers, no branches.
RAYLAB_AVX2 inline __m256i sortDescending(__m256i k) {
    k = sortLayer<0x99>(k, _mm256_shuffle_epi32(k, 0xb1));
    k = sortLayer<0xc3>(k, _mm256_shuffle_epi32(k, 0x4e));
    k = sortLayer<0xa5>(k, _mm256_shuffle_epi32(k, 0xb1));
    k = sortLayer<0x0f>(k, _mm256_permute2x128_si256(k, k, 0x01));
    k = sortLayer<0x33>(k, _mm256_shuffle_epi32(k, 0x4e));
    k = sortLayer<0x55>(k, _mm256_shuffle_epi32(k, 0xb1));
    return k;
}

// Pushes the hit children of a node (lanes of `hit` all ones), farthest first, and returns the
// nearest (not pushed). The order is by entry distance to within 8 ulps (the key's low 3 bits
// hold the lane), which only the visiting order depends on: each entry keeps its exact tNear.
// Writes kWideLanes entries from stack[size] on, whatever the count: the stack has room.
RAYLAB_AVX2 inline uint32_t pushChildren(const BvhWideNode& node, int mask, __m256 hit,
                                         __m256 tNear, StackEntry* stack, int& size) {
    if ((mask & (mask - 1)) == 0) {
        return node.child[__builtin_ctz(static_cast<unsigned>(mask))];
    }
    // Float bits made monotonic as signed integers (negative floats' magnitude bits flipped),
    // above INT_MIN for every non-NaN distance; missed lanes get INT_MIN and sort last.
    const __m256i bits = _mm256_castps_si256(tNear);
    const __m256i ordered =
        _mm256_xor_si256(bits, _mm256_srli_epi32(_mm256_srai_epi32(bits, 31), 1));
    const __m256i keys = _mm256_or_si256(_mm256_andnot_si256(_mm256_set1_epi32(7), ordered),
                                         _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    const __m256i sorted = sortDescending(
        _mm256_blendv_epi8(_mm256_set1_epi32(INT32_MIN), keys, _mm256_castps_si256(hit)));
    // permutevar8x32 reads the lane from each key's low 3 bits.
    const __m256i refs = _mm256_permutevar8x32_epi32(
        _mm256_load_si256(reinterpret_cast<const __m256i*>(node.child)), sorted);
    const __m256i ts = _mm256_permutevar8x32_epi32(bits, sorted);
    const __m256i lo = _mm256_unpacklo_epi32(refs, ts); // entries 0, 1 | 4, 5
    const __m256i hi = _mm256_unpackhi_epi32(refs, ts); // entries 2, 3 | 6, 7
    __m256i* top = reinterpret_cast<__m256i*>(stack + size);
    _mm256_storeu_si256(top, _mm256_permute2x128_si256(lo, hi, 0x20));
    _mm256_storeu_si256(top + 1, _mm256_permute2x128_si256(lo, hi, 0x31));
    size += __builtin_popcount(static_cast<unsigned>(mask)) - 1;
    // The nearest, the last entry written (not pushed), is the hit lanes' smallest key: found by
    // a reduction of its own, so that the walk goes on without waiting for the sort.
    __m256i smallest =
        _mm256_blendv_epi8(_mm256_set1_epi32(INT32_MAX), keys, _mm256_castps_si256(hit));
    smallest = _mm256_min_epi32(smallest, _mm256_shuffle_epi32(smallest, 0xb1));
    smallest = _mm256_min_epi32(smallest, _mm256_shuffle_epi32(smallest, 0x4e));
    smallest = _mm256_min_epi32(smallest, _mm256_permute2x128_si256(smallest, smallest, 0x01));
    return node.child[_mm256_cvtsi256_si32(smallest) & 7];
}

// What a traversal counts: nothing (the renderer's), or a TraversalCost.
struct NoCost {
    void node() {}
    void block() {}
};
struct CountCost {
    TraversalCost& cost;
    void node() { ++cost.nodes; }
    void block() { cost.triangles += kWideLanes; }
};

// Where a closest-hit walk of one ray through the 8-wide BVH stands between its steps
// (stepClosest): the ray, the closest hit so far, the next node or leaf and the stack's size
// (the ray's WideRay and the stack are kept beside it).
struct ClosestWalk {
    const Ray* original = nullptr; // the ray, for the lanes that go to the scalar test
    Hit best;
    float limit = 0.0f;   // best.t once a hit is found, ray.tMax before
    float bestDet = 1.0f; // best.u and best.v hold e1 and e2 until divided by this
    int size = 0;         // entries on the stack
    uint32_t ref = 0;     // the node or leaf to visit next
};

// Starts w at the root for `ray` (which must outlive the walk) and fills r; false for a ray
// WatertightRay calls invalid (it hits nothing).
RAYLAB_AVX2 inline bool startWalk(const Ray& ray, WideRay& r, ClosestWalk& w) {
    if (!makeWideRay(ray, r)) {
        return false;
    }
    w = ClosestWalk{};
    w.original = &ray;
    w.limit = ray.tMax;
    return true;
}

// A walk's answer once stepClosest has returned true: its best hit, with u = e1 / det and
// v = e2 / det divided out.
inline Hit finalHit(Hit best, float bestDet) {
    best.u /= bestDet;
    best.v /= bestDet;
    return best;
}

// One step of a closest-hit walk of `original` (r its constants): visits `ref` (a node: goes on
// to its nearest hit child and pushes the others on `stack`; a leaf: tests its triangles) and,
// after a leaf or a node with no child hit, pops the nearest pending entry that may still hold a
// closer (or tied) hit. True when none is left: finalHit(best, bestDet) is then the answer.
// With `prefetch`, the next node or leaf is prefetched (prefetchChild) as soon as it is known,
// for the interleaved walks, which visit it only after a step of each other walk. The stack has
// room for kWideStackSize + kWideLanes entries (pushChildren writes 8 above the top). The state
// comes as separate references so that a single walk keeps it in registers: with a ClosestWalk
// the single rays were 5% slower.
template <bool prefetch, class Cost>
RAYLAB_AVX2 inline bool stepClosest(const Bvh& bvh, const WideRay& r, const Ray& original,
                                    Hit& best, float& limit, float& bestDet, StackEntry* stack,
                                    int& size, uint32_t& ref, Cost& cost) {
    if (!isLeaf(ref)) {
        __m256 tNear, hit;
        const BvhWideNode& node = bvh.wideNodes[ref];
        cost.node();
        const int mask = hitChildren(node, r, limit, tNear, hit);
        if (mask != 0) {
            ref = pushChildren(node, mask, hit, tNear, stack, size);
            if constexpr (prefetch) {
                prefetchChild(bvh, ref);
            }
            return false;
        }
    } else {
        const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
        for (uint32_t b = blockCount(ref); b > 0; --b, ++block) {
            const LaneHits h = intersectBlock(*block, r.triangles);
            cost.block();
            const unsigned closer = h.hits & static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(
                                                 h.t, _mm256_set1_ps(limit), _CMP_LE_OQ)));
            if (closer != 0) {
                alignas(32) float t[kWideLanes], e1[kWideLanes], e2[kWideLanes], det[kWideLanes];
                _mm256_store_ps(t, h.t);
                _mm256_store_ps(e1, h.e1);
                _mm256_store_ps(e2, h.e2);
                _mm256_store_ps(det, h.det);
                for (unsigned m = closer; m != 0; m &= m - 1) {
                    const int lane = __builtin_ctz(m);
                    const uint32_t index = block->sceneIndex[lane];
                    if (closerHit(t[lane], index, best.t, best.triangle)) {
                        // u = e1 / det and v = e2 / det once the winner is known.
                        best = Hit{t[lane], e1[lane], e2[lane], index};
                        bestDet = det[lane];
                        limit = best.t;
                    }
                }
            }
            for (unsigned m = h.exact; m != 0; m &= m - 1) {
                const int lane = __builtin_ctz(m);
                const uint32_t index = block->sceneIndex[lane];
                float t, u, v;
                if (intersectLane(*block, lane, original, t, u, v) &&
                    closerHit(t, index, best.t, best.triangle)) {
                    best = Hit{t, u, v, index};
                    bestDet = 1.0f; // u and v are final
                    limit = best.t;
                }
            }
        }
    }
    for (;;) {
        if (size == 0) {
            return true;
        }
        const StackEntry e = stack[--size];
        if (e.tNear <= limit * kBoxRoundUp) {
            ref = e.ref;
            if constexpr (prefetch) {
                prefetchChild(bvh, ref);
            }
            return false;
        }
    }
}

template <bool prefetch, class Cost>
RAYLAB_AVX2 inline bool stepClosest(const Bvh& bvh, const WideRay& r, ClosestWalk& w,
                                    StackEntry* stack, Cost& cost) {
    return stepClosest<prefetch>(bvh, r, *w.original, w.best, w.limit, w.bestDet, stack, w.size,
                                 w.ref, cost);
}

template <class Cost>
RAYLAB_AVX2 Hit closestHitWideWith(const Bvh& bvh, const Ray& original, Cost cost) {
    WideRay r;
    if (!makeWideRay(original, r)) {
        return Hit{};
    }
    Hit best;
    float limit = original.tMax;
    float bestDet = 1.0f;
    StackEntry stack[kWideStackSize + kWideLanes];
    int size = 0;
    uint32_t ref = 0; // the root
    while (!stepClosest<false>(bvh, r, original, best, limit, bestDet, stack, size, ref, cost)) {
    }
    return finalHit(best, bestDet);
}

template <class Cost>
RAYLAB_AVX2 bool anyHitWideWith(const Bvh& bvh, const Ray& original, Cost cost) {
    WideRay r;
    if (!makeWideRay(original, r)) {
        return false;
    }
    const float limit = original.tMax;
    uint32_t stack[kWideStackSize];
    int size = 0;
    uint32_t ref = 0;
    for (;;) {
        if (!isLeaf(ref)) {
            __m256 tNear, hit;
            const BvhWideNode& node = bvh.wideNodes[ref];
            cost.node();
            const int mask = hitChildren(node, r, limit, tNear, hit);
            // Order does not matter for any hit: push all but one, descend into that one.
            if (mask != 0) {
                unsigned m = static_cast<unsigned>(mask);
                for (; (m & (m - 1)) != 0; m &= m - 1) {
                    stack[size++] = node.child[__builtin_ctz(m)];
                }
                ref = node.child[__builtin_ctz(m)];
                continue;
            }
        } else {
            const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
            for (uint32_t b = blockCount(ref); b > 0; --b, ++block) {
                const LaneHits h = intersectBlock(*block, r.triangles);
                cost.block();
                if (h.hits != 0) {
                    return true;
                }
                for (unsigned m = h.exact; m != 0; m &= m - 1) {
                    float t, u, v;
                    if (intersectLane(*block, __builtin_ctz(m), original, t, u, v)) {
                        return true;
                    }
                }
            }
        }
        if (size == 0) {
            return false;
        }
        ref = stack[--size];
    }
}

} // namespace

RAYLAB_AVX2 void closestHitsInterleaved(const Bvh& bvh, const Ray* rays, std::size_t count,
                                        Hit* hits) {
    WideRay wideRays[kInterleavedRays];
    ClosestWalk walks[kInterleavedRays];
    StackEntry stacks[kInterleavedRays][kWideStackSize + kWideLanes];
    Hit* answer[kInterleavedRays];
    std::size_t next = 0; // the next ray to start
    NoCost cost;
    // Starts walk w on the next valid ray (invalid ones hit nothing); false when none is left.
    const auto startNext = [&](int w) {
        while (next < count) {
            const std::size_t i = next++;
            if (startWalk(rays[i], wideRays[w], walks[w])) {
                answer[w] = &hits[i];
                return true;
            }
            hits[i] = Hit{};
        }
        return false;
    };
    unsigned running = 0; // bit w: walk w has a ray
    for (int w = 0; w < kInterleavedRays; ++w) {
        running |= startNext(w) ? 1u << w : 0u;
    }
    while (running != 0) {
        for (unsigned m = running; m != 0; m &= m - 1) {
            const int w = __builtin_ctz(m);
            if (stepClosest<true>(bvh, wideRays[w], walks[w], stacks[w], cost)) {
                *answer[w] = finalHit(walks[w].best, walks[w].bestDet);
                if (!startNext(w)) {
                    running &= ~(1u << w);
                }
            }
        }
    }
}

RAYLAB_AVX2 Hit closestHitWide(const Bvh& bvh, const Ray& ray) {
    return closestHitWideWith(bvh, ray, NoCost{});
}
RAYLAB_AVX2 bool anyHitWide(const Bvh& bvh, const Ray& ray) {
    return anyHitWideWith(bvh, ray, NoCost{});
}
RAYLAB_AVX2 Hit closestHitWideCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost) {
    return closestHitWideWith(bvh, ray, CountCost{cost});
}
RAYLAB_AVX2 bool anyHitWideCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost) {
    return anyHitWideWith(bvh, ray, CountCost{cost});
}

} // namespace raylab

#else // not x86: buildBvh never builds the wide form, so these are never called.

namespace raylab {
Hit closestHitWide(const Bvh&, const Ray&) { return Hit{}; }
bool anyHitWide(const Bvh&, const Ray&) { return false; }
Hit closestHitWideCounted(const Bvh&, const Ray&, TraversalCost&) { return Hit{}; }
void closestHitsInterleaved(const Bvh&, const Ray*, std::size_t, Hit*) {}
bool anyHitWideCounted(const Bvh&, const Ray&, TraversalCost&) { return false; }
} // namespace raylab

#endif
