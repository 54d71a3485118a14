#pragma once
// Bounding volume hierarchy over a scene's triangles, and the two queries the tracer needs:
// the closest hit (camera rays) and any hit (shadow rays). Both give exactly the answers of the
// brute-force loops in brute_force.h: the same triangle test, the same tie-breaking.
//
// A Bvh describes the scene's triangles as they were when it was built (their vertices, their
// count and their material indices): rebuild it whenever they change. It holds no material's
// colour, so materials may change without a rebuild.

#include "bvh/bvh_wide.h"
#include "ray.h"
#include "scene.h"
#include "uninitialised_allocator.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

namespace raylab {

// One node, 32 bytes. An inner node (count == 0) has its two children at nodes[index] and
// nodes[index + 1]; a leaf (count > 0) holds leaf triangles [index, index + count) (see
// Bvh::triangles for where they are stored).
struct BvhNode {
    glm::vec3 lower{0.0f};
    uint32_t index = 0;
    glm::vec3 upper{0.0f};
    uint32_t count = 0;
    bool isLeaf() const { return count != 0; }
};
static_assert(sizeof(BvhNode) == 32);

// A triangle as the BVH stores it: its vertices in leaf order, and which scene triangle it is.
struct BvhTriangle {
    glm::vec3 v0, v1, v2;
    uint32_t sceneIndex;
};

struct Bvh {
    // nodes[0] is the root; empty for a scene with no valid triangle, and, once the 8-wide form
    // is built from them, unless BvhBuildOptions::keepBinaryNodes asks to keep them.
    UninitialisedVector<BvhNode> nodes;
    // The leaf triangles, in leaf order, when there is no SIMD form. With the SIMD form, the
    // triangles are kept once, in triangleBlocks: this is empty, and leaf triangle i of a binary
    // leaf is lane i % 8 of triangleBlocks[i / 8] (leafTriangle() reads either).
    std::vector<BvhTriangle> triangles;
    std::size_t skippedTriangles = 0; // invalid ones (non-finite or zero area), never hit
    std::size_t leafReferences = 0;   // leaf triangles: valid triangles plus pre-split copies
    // How far every node box is widened on each side (world units), so that box tests never cull
    // a triangle the watertight test hits; a box made while tracing (a triangle's own bounds)
    // must be widened as much.
    float boxPad = 0.0f;
    // The largest |coordinate| of a valid triangle's vertex (world units; 0 when there is none):
    // what boxPad and the frustums' tolerance (bvh_frustum.h) are scaled by.
    float largestCoordinate = 0.0f;

    // The SIMD form (bvh_wide.h), built when the CPU runs AVX2 and BvhBuildOptions::simd is set.
    // Empty: closestHit and anyHit use the binary nodes and the scalar triangle test.
    // wideNodes[0] is the root; the blocks are in leaf order. resize() leaves new elements
    // unwritten: the build writes each one once, on the thread that fills it.
    UninitialisedVector<BvhWideNode> wideNodes;
    UninitialisedVector<BvhTriangleBlock> triangleBlocks;

    // Leaf triangle i of a binary leaf (BvhNode::index <= i < index + count).
    BvhTriangle leafTriangle(uint32_t i) const;
    // The box of every valid triangle (empty when there is none).
    Aabb bounds() const;

    std::size_t memoryBytes() const;
    // Levels of the binary nodes, or of the 8-wide nodes when only those are kept (0 when empty).
    int depth() const;
};

struct BvhBuildOptions {
    // Triangles per binary leaf, at most. When the 8-wide form is built and the binary nodes are
    // not kept, nodes of at most 8 references become leaves unsplit (one wide leaf holds them
    // anyway), so binary leaves may hold up to max(8, maxLeafSize).
    int maxLeafSize = 4;
    int binCount = 16; // SAH bins per axis
    int threads = 0;   // 0 = every hardware thread; the result does not depend on it
    bool simd = true;  // also build the 8-wide form when the CPU has AVX2
    // Keep the binary nodes beside the 8-wide form (tests of the binary tree itself). Without
    // them the 8-wide form is the whole BVH: the binary nodes cost 37 bytes a triangle (dragon).
    // A BVH without the 8-wide form always keeps them.
    bool keepBinaryNodes = false;
    // Extra references for pre-split triangles (bvh_presplit.h), as a fraction of the valid
    // triangles; 0 = none. Triangles of similar shape and size get none whatever the budget.
    // None by default: with the spatial splits below, pre-splitting Sponza (the one scene of
    // the bench that gets any) at 0.3 left its rays' work the same (counted) and cost 17% of
    // its build and 5% of its memory (PERFORMANCE.md, "What each change gained: the BVH build").
    float presplitBudget = 0.0f;
    // Spatial splits (bvh_spatial_split.h): at most this fraction of the references (after
    // pre-splitting) in extra references (0 = none; above 1 taken as 1: the build keeps room for
    // them all from the start). Tried only at nodes of at least 64 references with a budget
    // left of at least a twentieth of them, whose best object split leaves child boxes
    // overlapping by more than spatialSplitOverlap times the root's surface area (Stich et al.'s
    // alpha) and spatialSplitNodeOverlap times the node's own: the second test skips the many
    // small nodes of finely tessellated meshes, where spatial splits cost build time and gain
    // nothing (dragon).
    // Not tried at all in a scene whose every triangle spans at most 1/16 of the scene's extent on
    // every axis (an evenly tessellated scan: bvh_build.cpp).
    float spatialSplitBudget = 0.3f;
    float spatialSplitOverlap = 1e-4f;
    float spatialSplitNodeOverlap = 0.2f;
    // A spatial split is kept only where it lowers its node's SAH cost (against the node's best
    // object split) by at least this many times the fraction of the node's references it adds:
    // at 0.5 a split adding 10% more references must cut the cost by 5%. Each reference costs
    // memory (about 52 bytes) and build time; the thin triangles' top splits, adding 12% of
    // their nodes' references for 4-5% lower costs, took their BVH from 52 to 65 bytes a
    // triangle, over Embree's 57 (PERFORMANCE.md, "Spatial splits that pay for their
    // references"). 0: any split cheaper than the object split.
    float spatialSplitMinGain = 0.5f;
};

// True when this CPU can run the AVX2 traversal.
bool bvhSimdSupported();

Bvh buildBvh(const Scene& scene, const BvhBuildOptions& options = {});

// The working arrays of BVH builds (the references and their spare room, the subtrees' nodes and
// leaves, the binary nodes when only the 8-wide form is kept, the collapse's inputs and its wide
// subtrees' nodes and leaves), kept from one build to the next by a caller that builds again and
// again: raylab-bench's repeated builds, a program that rebuilds a changing scene. rebuildBvh
// leaves them allocated, so that the next build of about the same size writes memory already
// faulted in instead of new pages the system must map and zero (on the Zen 5 guest of
// PERFORMANCE.md, "Memory and page faults", about a tenth of a 2-thread Sponza build). Empty until
// a build uses it; then holds bytes(), 137-164 bytes a triangle of the largest scene built with it
// (the dragon's 121 MB), until destroyed. It also keeps the last build's threads, asleep between
// builds, so that a rebuild does not start them again (none for a build on one thread).
class BvhBuildMemory {
public:
    BvhBuildMemory();
    ~BvhBuildMemory();
    BvhBuildMemory(BvhBuildMemory&&) noexcept;
    BvhBuildMemory& operator=(BvhBuildMemory&&) noexcept;

    std::size_t bytes() const; // held now

    struct Arrays;    // internal to the build (bvh/build/bvh_build_memory.h)
    Arrays& arrays(); // made anew in a memory moved from

private:
    std::unique_ptr<Arrays> arrays_;
};

// Makes bvh the BVH of scene, the same as buildBvh(scene, options) (whatever bvh held before),
// in bvh's own arrays and memory's where they are large enough: only what grows is allocated.
// bvh.memoryBytes() then counts the capacity bvh keeps, which may exceed a fresh build's after
// a larger scene.
void rebuildBvh(const Scene& scene, const BvhBuildOptions& options, BvhBuildMemory& memory,
                Bvh& bvh);

// The closest hit with ray.tMin < t < ray.tMax; Hit::triangle is the scene's triangle index.
Hit closestHit(const Bvh& bvh, const Ray& ray);

// True when any triangle is hit with ray.tMin < t < ray.tMax; stops at the first one found.
bool anyHit(const Bvh& bvh, const Ray& ray);

// The closest hits of independent rays (incoherent ones: diffuse bounces), hits[i] =
// closestHit(bvh, rays[i]) for i < count, bit for bit. Where interleavesRays(bvh), the rays are
// walked several at a time, a node or leaf of each in turn, so that one ray's wait on memory
// overlaps the others' work; else one after the other.
void closestHits(const Bvh& bvh, const Ray* rays, std::size_t count, Hit* hits);

// closestHits' rule: the 8-wide form's nodes and triangle blocks take more than `fromBytes`, by
// default interleaveFromBytes() (below), so that most of a walk's reads miss the caches.
bool interleavesRays(const Bvh& bvh, std::size_t fromBytes);
bool interleavesRays(const Bvh& bvh);

// The size from which closestHits interleaves: the CPU's level 3 cache as the system reports it
// (interleaveFromBytes() asks glibc once), or kInterleaveWithoutCacheSize where it reports none.
// Measured on raylab-bench's bounce rays, interleaved over one by one (PERFORMANCE.md,
// "Interleaved walks (`closestHits`)"): on the Zen 4 (a 32 MiB cache), the bounce rays alone, 1
// thread: the dragon (45 MiB) 1.14-1.25x, the dragon's triangles cut to 85% (38 MiB) 1.06-1.08x, to
// 70% (32 MiB) 1.01-1.05x, to half (22 MiB) 0.96-0.99x, Sponza (16 MiB) 0.75-0.83x, the bunny (4
// MiB) 0.90-0.94x. On the Intel Xeon (300 MiB), where the dragon and the 980,000-triangle terrain
// (52 MiB) fit, the whole bounce workload over Embree's was as high or higher one by one: on 2
// threads the dragon's 1.18-1.35 against 1.11-1.20.
std::size_t interleaveFromBytes(long lastLevelCacheBytes);
std::size_t interleaveFromBytes();
inline constexpr std::size_t kInterleaveWithoutCacheSize = std::size_t{32} << 20;

// What one query cost: the BVH nodes it visited and the triangles it tested (8 a block on the
// 8-wide form, whose SIMD test takes a block at once). The answers are closestHit's and anyHit's.
struct TraversalCost {
    uint32_t nodes = 0;
    uint32_t triangles = 0;
};
Hit closestHitCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost);
bool anyHitCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost);

// The scalar reference: intersectTriangle and the scalar box test, walking the binary nodes when
// the Bvh keeps them, else the 8-wide nodes one child and one lane at a time. The SIMD path
// gives exactly its answers (t, u, v, triangle) on every ray.
Hit closestHitScalar(const Bvh& bvh, const Ray& ray);
bool anyHitScalar(const Bvh& bvh, const Ray& ray);

} // namespace raylab
