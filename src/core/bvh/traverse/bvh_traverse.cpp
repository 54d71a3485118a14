// Scalar traversal (the reference) of the binary BVH, or of the 8-wide one when the binary nodes
// are not kept, and the dispatch to the SIMD traversal.

#include "bvh/bvh.h"
#include "bvh/traverse/bvh_box_ray.h"
#include "bvh/traverse/bvh_wide_traverse.h"
#include "triangle_intersection.h"

#include <unistd.h>

namespace raylab {

namespace {

constexpr int kScalarStackSize = 128; // the build bounds the binary depth well below this

bool hitNode(const BoxRay& r, const BvhNode& node, float limit, float& tNear) {
    const float bounds[2][3] = {{node.lower.x, node.lower.y, node.lower.z},
                                {node.upper.x, node.upper.y, node.upper.z}};
    return hitBox(r, bounds, limit, tNear);
}

// Visits the leaves whose boxes the ray enters, nearest child first, skipping nodes that start
// beyond limit(). visitLeaf(node) returns true to stop the traversal.
// What a traversal counts: nothing, or a TraversalCost.
struct NoCost {
    void node() {}
    void triangles(uint32_t) {}
};
struct CountCost {
    TraversalCost& cost;
    void node() { ++cost.nodes; }
    void triangles(uint32_t n) { cost.triangles += n; }
};

template <class Limit, class VisitLeaf, class Cost>
void traverseBinary(const Bvh& bvh, const BoxRay& r, Limit limit, VisitLeaf visitLeaf, Cost cost) {
    struct Entry {
        uint32_t node;
        float tNear;
    };
    Entry stack[kScalarStackSize];
    int size = 0;
    float tRoot;
    if (!hitNode(r, bvh.nodes[0], limit(), tRoot)) {
        return;
    }
    stack[size++] = {0, tRoot};
    while (size > 0) {
        const Entry e = stack[--size];
        if (e.tNear > limit() * kBoxRoundUp) {
            continue;
        }
        const BvhNode& node = bvh.nodes[e.node];
        cost.node();
        if (node.isLeaf()) {
            cost.triangles(node.count);
            if (visitLeaf(node)) {
                return;
            }
            continue;
        }
        float t0, t1;
        const bool hit0 = hitNode(r, bvh.nodes[node.index], limit(), t0);
        const bool hit1 = hitNode(r, bvh.nodes[node.index + 1], limit(), t1);
        if (hit0 && hit1) {
            const bool firstNear = t0 <= t1;
            stack[size++] = {firstNear ? node.index + 1 : node.index, firstNear ? t1 : t0};
            stack[size++] = {firstNear ? node.index : node.index + 1, firstNear ? t0 : t1};
        } else if (hit0) {
            stack[size++] = {node.index, t0};
        } else if (hit1) {
            stack[size++] = {node.index + 1, t1};
        }
    }
}

// The closest-hit rule, one triangle at a time: the nearest t, a tie to the lower scene index.
// limit: the t of the best so far (the ray's tMax before), where traversal stops looking.
struct ClosestTest {
    const WatertightRay& ray;
    float limit;
    Hit best;
    // Never stops the traversal.
    bool operator()(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2, uint32_t index) {
        float t, u, v;
        if (intersectTriangle(ray, v0, v1, v2, t, u, v) &&
            closerHit(t, index, best.t, best.triangle)) {
            best = Hit{t, u, v, index};
            limit = t;
        }
        return false;
    }
};

// The any-hit rule: the first triangle hit stops the traversal.
struct AnyTest {
    const WatertightRay& ray;
    float limit; // the ray's tMax
    bool found = false;
    bool operator()(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2, uint32_t) {
        float t, u, v;
        found = intersectTriangle(ray, v0, v1, v2, t, u, v);
        return found;
    }
};

// At most 7 entries wait per level of the 8-wide tree, which is no deeper than the binary one.
constexpr int kWideScalarStackSize = 7 * kScalarStackSize + 1;

// Visits the triangle blocks of the leaves whose boxes the ray enters, one child box at a time
// with the scalar slab test, nearest child first, skipping entries that start beyond limit().
// visitBlock(block) returns true to stop the traversal.
template <class Limit, class VisitBlock, class Cost>
void traverseWideScalar(const Bvh& bvh, const BoxRay& r, Limit limit, VisitBlock visitBlock,
                        Cost cost) {
    struct Entry {
        uint32_t child;
        float tNear;
    };
    Entry stack[kWideScalarStackSize];
    int size = 0;
    stack[size++] = {0, r.tMin}; // the root node has no box of its own
    while (size > 0) {
        const Entry e = stack[--size];
        if (e.tNear > limit() * kBoxRoundUp) {
            continue;
        }
        if ((e.child & kWideLeafFlag) != 0) {
            const uint32_t first = e.child & kWideFirstBlockMask;
            const uint32_t count = ((e.child >> kWideBlockShift) & (kWideMaxLeafBlocks - 1)) + 1;
            for (uint32_t b = first; b < first + count; ++b) {
                cost.triangles(kWideLanes);
                if (visitBlock(bvh.triangleBlocks[b])) {
                    return;
                }
            }
            continue;
        }
        const BvhWideNode& node = bvh.wideNodes[e.child];
        cost.node();
        Entry hits[kWideLanes];
        int hitCount = 0;
        for (int c = 0; c < kWideLanes; ++c) {
            if (node.child[c] == kWideEmpty) {
                continue;
            }
            const float bounds[2][3] = {{node.lower[0][c], node.lower[1][c], node.lower[2][c]},
                                        {node.upper[0][c], node.upper[1][c], node.upper[2][c]}};
            float tNear;
            if (hitBox(r, bounds, limit(), tNear)) {
                // Insertion by distance, farthest first, so the nearest is popped first.
                int at = hitCount++;
                while (at > 0 && hits[at - 1].tNear < tNear) {
                    hits[at] = hits[at - 1];
                    --at;
                }
                hits[at] = {node.child[c], tNear};
            }
        }
        for (int i = 0; i < hitCount; ++i) {
            stack[size++] = hits[i];
        }
    }
}

// Runs `test` (ClosestTest or AnyTest) on the triangles the ray's walk reaches: through the
// binary nodes when the Bvh keeps them, else through the 8-wide nodes one child and lane at a
// time.
template <class Test, class Cost>
void walkScalar(const Bvh& bvh, const Ray& ray, Test& test, Cost cost) {
    if (!test.ray.valid) {
        return;
    }
    const auto limit = [&] { return test.limit; };
    if (!bvh.nodes.empty()) {
        traverseBinary(
            bvh, BoxRay(ray), limit,
            [&](const BvhNode& leaf) {
                for (uint32_t i = leaf.index; i < leaf.index + leaf.count; ++i) {
                    const BvhTriangle tri = bvh.leafTriangle(i);
                    if (test(tri.v0, tri.v1, tri.v2, tri.sceneIndex)) {
                        return true;
                    }
                }
                return false;
            },
            cost);
    } else if (!bvh.wideNodes.empty()) {
        traverseWideScalar(
            bvh, BoxRay(ray), limit,
            [&](const BvhTriangleBlock& block) {
                for (int lane = 0; lane < kWideLanes; ++lane) {
                    glm::vec3 v[3];
                    for (int k = 0; k < 3; ++k) {
                        v[k] = glm::vec3(block.vertex[k][0][lane], block.vertex[k][1][lane],
                                         block.vertex[k][2][lane]);
                    }
                    if (test(v[0], v[1], v[2], block.sceneIndex[lane])) {
                        return true;
                    }
                }
                return false;
            },
            cost);
    }
}

template <class Cost> Hit closestHitScalarWith(const Bvh& bvh, const Ray& ray, Cost cost) {
    const WatertightRay wray(ray);
    ClosestTest test{wray, ray.tMax, Hit{}};
    walkScalar(bvh, ray, test, cost);
    return test.best;
}

template <class Cost> bool anyHitScalarWith(const Bvh& bvh, const Ray& ray, Cost cost) {
    const WatertightRay wray(ray);
    AnyTest test{wray, ray.tMax};
    walkScalar(bvh, ray, test, cost);
    return test.found;
}

} // namespace

Hit closestHitScalar(const Bvh& bvh, const Ray& ray) {
    return closestHitScalarWith(bvh, ray, NoCost{});
}

bool anyHitScalar(const Bvh& bvh, const Ray& ray) { return anyHitScalarWith(bvh, ray, NoCost{}); }

Hit closestHitCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost) {
    if (bvh.wideNodes.empty()) {
        return closestHitScalarWith(bvh, ray, CountCost{cost});
    }
    return closestHitWideCounted(bvh, ray, cost);
}

bool anyHitCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost) {
    if (bvh.wideNodes.empty()) {
        return anyHitScalarWith(bvh, ray, CountCost{cost});
    }
    return anyHitWideCounted(bvh, ray, cost);
}

Hit closestHit(const Bvh& bvh, const Ray& ray) {
    if (bvh.wideNodes.empty()) {
        return closestHitScalar(bvh, ray);
    }
    return closestHitWide(bvh, ray);
}

bool anyHit(const Bvh& bvh, const Ray& ray) {
    if (bvh.wideNodes.empty()) {
        return anyHitScalar(bvh, ray);
    }
    return anyHitWide(bvh, ray);
}

std::size_t interleaveFromBytes(long lastLevelCacheBytes) {
    return lastLevelCacheBytes > 0 ? static_cast<std::size_t>(lastLevelCacheBytes)
                                   : kInterleaveWithoutCacheSize;
}

std::size_t interleaveFromBytes() {
    // The level 3 cache's size as glibc reports it (0 or -1 where it knows none), asked once.
    static const std::size_t fromBytes = [] {
        long bytes = 0;
#if defined(_SC_LEVEL3_CACHE_SIZE)
        bytes = sysconf(_SC_LEVEL3_CACHE_SIZE);
#endif
        return interleaveFromBytes(bytes);
    }();
    return fromBytes;
}

bool interleavesRays(const Bvh& bvh, std::size_t fromBytes) {
    const std::size_t bytes = bvh.wideNodes.size() * sizeof(BvhWideNode) +
                              bvh.triangleBlocks.size() * sizeof(BvhTriangleBlock);
    return !bvh.wideNodes.empty() && bytes > fromBytes;
}

bool interleavesRays(const Bvh& bvh) { return interleavesRays(bvh, interleaveFromBytes()); }

void closestHits(const Bvh& bvh, const Ray* rays, std::size_t count, Hit* hits) {
    if (interleavesRays(bvh)) {
        closestHitsInterleaved(bvh, rays, count, hits);
        return;
    }
    for (std::size_t i = 0; i < count; ++i) {
        hits[i] = closestHit(bvh, rays[i]);
    }
}

bool bvhSimdSupported() {
#if defined(__x86_64__) || defined(__i386__)
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

} // namespace raylab
