// Binned SAH build of the binary BVH (bvh.h).
//
// Every valid triangle becomes a primitive record (its box and scene index); pre-splitting may
// add references (bvh_presplit.h). Nodes are split as bvh_build_subtree.h describes. The top of
// the tree, down to subtrees of a size that depends only on the triangle count, is built on
// all threads (its large nodes each by chunks on every thread, its smaller ones several at a
// time: bvh_build_top.cpp); those subtrees are then built in parallel, each into its own slots
// with its leaves in depth-first order, and assembled in a fixed order, so the result is the same
// whatever the thread count.

#include "bvh/build/bvh_binning.h"
#include "bvh/build/bvh_build_memory.h"
#include "bvh/build/bvh_build_subtree.h"
#include "bvh/build/bvh_build_team.h"
#include "bvh/build/bvh_collapse.h"
#include "bvh/build/bvh_presplit.h"
#include "bvh/build/bvh_spatial_split.h"
#include "bvh/bvh.h"
#include "render/parallel_tiles.h"
#include "triangle_validity_sse.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <numeric>
#include <vector>

namespace raylab {

namespace {

constexpr std::size_t kMinTaskSize = 4096;  // smallest subtree worth a parallel task
constexpr std::size_t kBoundsChunk = 65536; // records per chunk of the root's bounds
constexpr std::size_t kRecordChunk = 16384; // triangles per chunk of makeRecords

// Makes `records` one record per valid triangle, in scene order; counts the others in `skipped`,
// and finds the records' bounds (as boundsOf would) and the widest triangle on each axis (upper -
// lower, world units).
// Chunk c writes its records from c * kRecordChunk on, in the array itself; only where
// triangles were skipped do later chunks move down after. The array has capacity for
// `extraRoom` times as many records more (its own kept where it is that large already).
void makeRecords(const Scene& scene, float extraRoom, BuildTeam& team, RecordVector& records,
                 std::size_t& skipped, RecordBounds& bounds, glm::vec3& widest) {
    const std::size_t triangles = scene.triangles.size();
    const std::size_t chunks = (triangles + kRecordChunk - 1) / kRecordChunk;
    records.clear();
    records.reserve(triangles +
                    static_cast<std::size_t>(extraRoom * static_cast<double>(triangles)));
    records.resize(triangles);
    struct ChunkFacts { // one chunk's, accumulated in registers and stored once
        std::size_t made = 0;
        RecordBounds bounds;
        glm::vec3 widest{0.0f};
    };
    std::vector<ChunkFacts> facts(chunks);
    team.forEach(chunks, [&](std::size_t c) {
        PrimRecord* out = records.data() + c * kRecordChunk;
        std::size_t made = 0;
        RecordBounds chunkBounds;
        __m128 chunkWidest = _mm_setzero_ps();
        for (std::size_t i = c * kRecordChunk; i < std::min(triangles, (c + 1) * kRecordChunk);
             ++i) {
            const TriangleLanes t(scene.triangles[i]);
            if (!isValidTriangle(t)) {
                continue;
            }
            const __m128 lower = _mm_min_ps(_mm_min_ps(t.v2, t.v1), t.v0);
            const __m128 upper = _mm_max_ps(_mm_max_ps(t.v2, t.v1), t.v0);
            chunkWidest = _mm_max_ps(_mm_sub_ps(upper, lower), chunkWidest);
            // The record: lane 3 of the lower corner the scene index, of the upper one 0 (as
            // TriangleLanes' lanes 3 are).
            const __m128 index =
                _mm_castsi128_ps(_mm_slli_si128(_mm_cvtsi32_si128(static_cast<int>(i)), 12));
            const __m128 recordLower = _mm_or_ps(lower, index);
            _mm_storeu_ps(&out[made].lower.x, recordLower);
            _mm_storeu_ps(&out[made].upper.x, upper);
            chunkBounds.add(recordLower, upper); // as RecordBounds::add(out[made])
            ++made;
        }
        alignas(16) float w[4];
        _mm_store_ps(w, chunkWidest);
        facts[c] = ChunkFacts{made, chunkBounds, glm::vec3(w[0], w[1], w[2])};
    });
    std::size_t at = 0;
    for (std::size_t c = 0; c < chunks; ++c) {
        if (at != c * kRecordChunk) {
            std::copy_n(records.begin() + static_cast<std::ptrdiff_t>(c * kRecordChunk),
                        facts[c].made, records.begin() + static_cast<std::ptrdiff_t>(at));
        }
        at += facts[c].made;
        widest = glm::max(widest, facts[c].widest);
        bounds.merge(facts[c].bounds); // in chunk order, as boundsOnTeam merges
    }
    skipped = triangles - at;
    records.resize(at);
}

// Bounds of all records, chunk by chunk on the team, merged in chunk order.
RecordBounds boundsOnTeam(const RecordVector& records, BuildTeam& team) {
    const std::size_t chunks = (records.size() + kBoundsChunk - 1) / kBoundsChunk;
    std::vector<RecordBounds> parts(chunks);
    team.forEach(chunks, [&](std::size_t i) {
        const std::size_t first = i * kBoundsChunk;
        const std::size_t last = std::min(records.size(), first + kBoundsChunk);
        parts[i] = boundsOf(records.data() + first, records.data() + last);
    });
    RecordBounds all;
    for (const RecordBounds& p : parts) {
        all.merge(p);
    }
    return all;
}

// Splitting triangles, before the build (pre-splits) or in it (spatial splits), pays where
// triangles are large against the nodes they cross (Sponza's floors, walls and columns). In a
// scene whose every triangle spans at most one spatial bin of the whole scene on every axis (a
// scanned surface, evenly tessellated: the bunny's and the dragon's widest reach a 25th)
// spatial splits won at few nodes for about 1% of those nodes' cost, pre-splitting gave the
// dragon one reference for 28 ms, and the bunny and the dragon traced as fast without them and
// built 16-30% faster (PERFORMANCE.md).
bool hasTriangleWiderThanASpatialBin(const glm::vec3& widest, const Aabb& scene) {
    const glm::vec3 extent = scene.extent();
    for (int a = 0; a < 3; ++a) {
        if (widest[a] * static_cast<float>(kSpatialBins) > extent[a]) {
            return true;
        }
    }
    return false;
}

// Where each part of the tree goes in the BVH's arrays.
struct Layout {
    std::vector<uint32_t> nodeAt;    // subtree i's local node k > 0 goes to nodeAt[i] + k - 1
    std::vector<uint32_t> recordAt;  // subtree i's records start here
    std::vector<uint32_t> topLeafAt; // per top node: where a top leaf's records go
    std::size_t nodes = 0, records = 0;
};

// Nodes: the top's, then each subtree's but its root (which takes its slot in the top), in
// the order of `deferred`. Leaf references: depth-first, left child first.
Layout layOut(const Subtree& top, const std::vector<BuildTask>& deferred,
              const std::vector<Subtree>& subtrees) {
    Layout layout;
    std::vector<int> subtreeAt(top.nodes.size(), -1); // top node -> the subtree it roots
    layout.nodeAt.resize(subtrees.size());
    layout.recordAt.resize(subtrees.size());
    layout.topLeafAt.resize(top.nodes.size());
    layout.nodes = top.nodes.size();
    for (std::size_t i = 0; i < subtrees.size(); ++i) {
        subtreeAt[deferred[i].slot] = static_cast<int>(i);
        layout.nodeAt[i] = static_cast<uint32_t>(layout.nodes);
        layout.nodes += subtrees[i].nodes.size() - 1;
    }
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
        const uint32_t n = stack.back();
        stack.pop_back();
        if (subtreeAt[n] >= 0) {
            layout.recordAt[static_cast<std::size_t>(subtreeAt[n])] =
                static_cast<uint32_t>(layout.records);
            layout.records += subtrees[static_cast<std::size_t>(subtreeAt[n])].leafTriangles.size();
        } else if (top.nodes[n].isLeaf()) {
            layout.topLeafAt[n] = static_cast<uint32_t>(layout.records);
            layout.records += top.nodes[n].count;
        } else {
            stack.push_back(top.nodes[n].index + 1);
            stack.push_back(top.nodes[n].index);
        }
    }
    return layout;
}

// Where the leaves' triangles go: the BVH's own copies (the scalar form), or only their scene
// indices (for the 8-wide form, which copies the triangles into its blocks itself).
struct LeafOutput {
    BvhTriangle* triangles = nullptr;
    uint32_t* sceneIndices = nullptr;
};

// Writes the leaf references of scene triangles first[0 .. count), from leaf triangle `at` on.
void writeLeaves(const Scene& scene, const uint32_t* first, std::size_t count, std::size_t at,
                 const LeafOutput& out) {
    for (std::size_t i = 0; i < count; ++i) {
        const uint32_t index = first[i];
        if (out.triangles) {
            const Triangle& t = scene.triangles[index];
            out.triangles[at + i] = BvhTriangle{t.v0, t.v1, t.v2, index};
        } else {
            out.sceneIndices[at + i] = index;
        }
    }
}

// Where each deferred subtree's arrays go in the two arrays they share: subtree i's nodes in
// slot i of one, its leaf references in slot i of the other. A subtree's leaves hold each of its
// references once: room() of them at most, which its slot holds. Its nodes are 2 * leaves - 1:
// where every node of up to 8 references is a leaf
// (`leavesOfUpTo8`, the 8-wide form's), 0.32-0.37 of its references on the meshes of
// PERFORMANCE.md (0.41 at most in one subtree), so its slot holds half its references and 16
// more; otherwise count + 1. Larger slots would cost: every page of the shared array is faulted
// in, used or not. A subtree that needs more nodes moves them out of its slot (SlotArray).
struct SubtreeSlots {
    SlotLayout<BvhNode> nodes;
    SlotLayout<uint32_t> leaves;
};

SubtreeSlots subtreeSlots(const std::vector<BuildTask>& deferred, bool leavesOfUpTo8) {
    SubtreeSlots slots;
    for (const BuildTask& task : deferred) {
        slots.nodes.append(leavesOfUpTo8 ? task.count / 2 + 16 : task.count + std::size_t{1});
        slots.leaves.append(task.room());
    }
    return slots;
}

// Box tests round; the watertight test's edge decisions round too. Every node box is widened by
// `pad` so that box tests never cull a triangle the watertight test hits.
BvhNode padded(BvhNode node, float pad) {
    node.lower -= glm::vec3(pad);
    node.upper += glm::vec3(pad);
    return node;
}

// Fills bvh.nodes from the top and its subtrees, and the leaves' triangles (bvh.triangles, or,
// when `forWide`, only their scene indices in `sceneIndices` and each node's span of them in
// `spans`, as the 8-wide form wants them), subtrees on the team.
void assemble(const Scene& scene, const Subtree& top, const std::vector<BuildTask>& deferred,
              const std::vector<Subtree>& subtrees, float pad, bool forWide, BuildTeam& team,
              Bvh& bvh, UninitialisedVector<uint32_t>& sceneIndices,
              UninitialisedVector<LeafSpan>& spans) {
    const Layout layout = layOut(top, deferred, subtrees);
    bvh.nodes.resize(layout.nodes);
    LeafOutput out;
    if (forWide) {
        sceneIndices.resize(layout.records);
        out.sceneIndices = sceneIndices.data();
        spans.resize(layout.nodes);
    } else {
        bvh.triangles.resize(layout.records);
        out.triangles = bvh.triangles.data();
    }
    for (std::size_t n = 0; n < top.nodes.size(); ++n) {
        BvhNode node = top.nodes[n];
        if (node.isLeaf()) {
            writeLeaves(scene, top.leafTriangles.data() + node.index, node.count,
                        layout.topLeafAt[n], out);
            node.index = layout.topLeafAt[n];
        }
        bvh.nodes[n] = padded(node, pad); // a subtree's root overwrites its slot below
    }
    team.forEach(subtrees.size(), [&](std::size_t i) {
        const Subtree& sub = subtrees[i];
        const uint32_t nodeOffset = layout.nodeAt[i] - 1, recordOffset = layout.recordAt[i];
        for (std::size_t k = 0; k < sub.nodes.size(); ++k) {
            BvhNode node = sub.nodes[k];
            node.index += node.isLeaf() ? recordOffset : nodeOffset;
            bvh.nodes[k == 0 ? deferred[i].slot : nodeOffset + k] = padded(node, pad);
        }
        writeLeaves(scene, sub.leafTriangles.data(), sub.leafTriangles.size(), recordOffset, out);
        if (forWide) { // its nodes but the root, which lies among the top's
            spanBinaryNodes(bvh.nodes.data(), nodeOffset + 1, nodeOffset + sub.nodes.size(),
                            spans.data());
        }
    });
    if (forWide) {
        spanBinaryNodes(bvh.nodes.data(), 0, top.nodes.size(), spans.data());
    }
    bvh.leafReferences = layout.records;
}

// Empties bvh as a fresh Bvh is, its arrays keeping their capacity.
void clearKeepingArrays(Bvh& bvh) {
    auto nodes = std::move(bvh.nodes);
    auto triangles = std::move(bvh.triangles);
    auto wideNodes = std::move(bvh.wideNodes);
    auto triangleBlocks = std::move(bvh.triangleBlocks);
    bvh = Bvh{};
    nodes.clear();
    triangles.clear();
    wideNodes.clear();
    triangleBlocks.clear();
    bvh.nodes = std::move(nodes);
    bvh.triangles = std::move(triangles);
    bvh.wideNodes = std::move(wideNodes);
    bvh.triangleBlocks = std::move(triangleBlocks);
}

} // namespace

Bvh buildBvh(const Scene& scene, const BvhBuildOptions& options) {
    BvhBuildMemory memory;
    Bvh bvh;
    rebuildBvh(scene, options, memory, bvh);
    return bvh;
}

void rebuildBvh(const Scene& scene, const BvhBuildOptions& options, BvhBuildMemory& memory,
                Bvh& bvh) {
    clearKeepingArrays(bvh);
    BvhBuildMemory::Arrays& kept = memory.arrays();
    kept.clear();
    if (bvh.nodes.capacity() < kept.binaryNodes.capacity()) {
        bvh.nodes.swap(kept.binaryNodes); // kept there by the last build that dropped them
    }
    // A scene smaller than one subtree task gains nothing from more threads than one.
    BuildTeam alone(1); // no threads of its own
    BuildTeam& team = scene.triangles.size() < 2 * kMinTaskSize
                          ? alone
                          : kept.teamOf(resolveThreadCount(options.threads));
    RecordBounds recordBounds;      // of the records of the valid triangles
    glm::vec3 widestTriangle{0.0f}; // on each axis, before pre-splitting
    // Spatial splits add at most this fraction of references (BvhBuildOptions; NaN: none).
    const float spatialBudget =
        options.spatialSplitBudget > 0.0f ? std::min(options.spatialSplitBudget, 1.0f) : 0.0f;
    RecordVector& records = kept.records;
    makeRecords(scene, spatialBudget, team, records, bvh.skippedTriangles, recordBounds,
                widestTriangle);
    if (records.empty()) {
        return;
    }
    const Aabb sceneBox = recordBounds.box.toAabb(); // of the valid triangles
    // The largest |coordinate| of a valid vertex.
    const glm::vec3 farthest = glm::max(glm::abs(sceneBox.lower), glm::abs(sceneBox.upper));
    const float magnitude = std::max({farthest.x, farthest.y, farthest.z});

    // Split boxes are widened by 2^-21 of the largest coordinate (several ulps of any vertex
    // coordinate), and node boxes by 2^-19 (far above the rounding of box tests and of the
    // watertight test's edge decisions, and far below any visible size).
    const float slack = std::ldexp(std::max(magnitude, 1e-30f), -21);
    const float pad = std::ldexp(std::max(magnitude, 1e-30f), -19);
    bvh.boxPad = pad;
    bvh.largestCoordinate = magnitude;
    const bool splitsMayPay = hasTriangleWiderThanASpatialBin(widestTriangle, sceneBox);
    BuildTask root;
    root.bounds = recordBounds;
    if (splitsMayPay && presplitRecords(scene, options.presplitBudget, slack, team, records)) {
        root.bounds = boundsOnTeam(records, team);
    }
    const bool wide = options.simd && bvhSimdSupported();
    BuildContext context;
    if (wide && !options.keepBinaryNodes) {
        context.leafAtMost = kLeafMerge; // the binary nodes are dropped after the collapse
    }
    if (spatialBudget > 0.0f && splitsMayPay) {
        context.scene = &scene;
        context.slack = slack;
        context.minOverlapArea = options.spatialSplitOverlap * root.bounds.box.toAabb().area();
        context.minNodeOverlap = options.spatialSplitNodeOverlap;
        context.minGainPerReference = // negative or NaN: 0
            options.spatialSplitMinGain > 0.0f ? options.spatialSplitMinGain : 0.0f;
    }
    const SubtreeBuilder builder(options, context);
    const std::size_t total = records.size();
    root.count = static_cast<uint32_t>(total);
    // The references' two ranges with room for every reference the splits may add
    // (BuildTask), allocated once.
    root.splitBudget =
        context.scene ? static_cast<uint32_t>(spatialBudget * static_cast<double>(total)) : 0;
    records.resize(root.room());
    RecordVector& spare = kept.spare;
    spare.resize(root.room());
    root.first = records.data();
    root.spare = spare.data();

    // The top, on the whole team.
    Subtree top;
    top.nodes.resize(1);
    std::vector<BuildTask> deferred;
    builder.buildTop(top, root, team, std::max(kMinTaskSize, total / 64), deferred);

    // The subtrees, largest first (the order they finish in does not matter), each in its slots
    // of two arrays shared by them all (subtreeSlots, sizeSharedSlots).
    std::vector<Subtree> subtrees(deferred.size());
    const SubtreeSlots slots = subtreeSlots(deferred, context.leafAtMost >= kLeafMerge);
    sizeSharedSlots(kept.subtreeNodes, slots.nodes);
    sizeSharedSlots(kept.subtreeLeaves, slots.leaves);
    std::vector<std::size_t> order(deferred.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return deferred[a].count > deferred[b].count;
    });
    team.forEach(order.size(), [&](std::size_t k) {
        const std::size_t i = order[k];
        BuildTask local = deferred[i];
        local.slot = 0;
        // Built in the job's own Subtree and moved in once: the subtrees lie side by side, and
        // growing them from several threads would share their cache lines.
        Subtree subtree;
        subtree.nodes = slotIn(kept.subtreeNodes, slots.nodes, i);
        subtree.leafTriangles = slotIn(kept.subtreeLeaves, slots.leaves, i);
        subtree.nodes.resize(1);
        builder.buildSubtree(subtree, local);
        subtrees[i] = std::move(subtree);
    });
    UninitialisedVector<uint32_t>& sceneIndices = kept.sceneIndices;
    UninitialisedVector<LeafSpan>& spans = kept.spans;
    assemble(scene, top, deferred, subtrees, pad, wide, team, bvh, sceneIndices, spans);
    std::vector<Subtree>().swap(subtrees);
    if (wide && !buildWideBvh(bvh, scene, sceneIndices, spans, options.keepBinaryNodes, team,
                              kept.collapse)) {
        // The tree does not fit the wide form: the binary form keeps its own triangles.
        bvh.triangles.resize(sceneIndices.size());
        for (std::size_t i = 0; i < sceneIndices.size(); ++i) {
            const Triangle& t = scene.triangles[sceneIndices[i]];
            bvh.triangles[i] = BvhTriangle{t.v0, t.v1, t.v2, sceneIndices[i]};
        }
    }
    if (!bvh.wideNodes.empty() && !options.keepBinaryNodes) {
        // The 8-wide form holds the tree and triangles; the binary nodes' array is kept for the
        // next build.
        kept.binaryNodes = std::move(bvh.nodes);
        bvh.nodes = UninitialisedVector<BvhNode>();
    }
}

std::size_t Bvh::memoryBytes() const {
    return nodes.capacity() * sizeof(BvhNode) + triangles.capacity() * sizeof(BvhTriangle) +
           wideNodes.capacity() * sizeof(BvhWideNode) +
           triangleBlocks.capacity() * sizeof(BvhTriangleBlock);
}

BvhTriangle Bvh::leafTriangle(uint32_t i) const {
    if (!triangles.empty()) {
        return triangles[i];
    }
    const BvhTriangleBlock& block = triangleBlocks[i / kWideLanes];
    const uint32_t lane = i % kWideLanes;
    BvhTriangle t{};
    glm::vec3* v[3] = {&t.v0, &t.v1, &t.v2};
    for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) {
            (*v[k])[a] = block.vertex[k][a][lane];
        }
    }
    t.sceneIndex = block.sceneIndex[lane];
    return t;
}

Aabb Bvh::bounds() const {
    Aabb box;
    if (!nodes.empty()) {
        box.lower = nodes[0].lower;
        box.upper = nodes[0].upper;
    } else if (!wideNodes.empty()) {
        const BvhWideNode& root = wideNodes[0];
        for (int c = 0; c < kWideLanes; ++c) {
            if (root.child[c] != kWideEmpty) {
                box.extend(glm::vec3(root.lower[0][c], root.lower[1][c], root.lower[2][c]));
                box.extend(glm::vec3(root.upper[0][c], root.upper[1][c], root.upper[2][c]));
            }
        }
    }
    return box;
}

int Bvh::depth() const {
    if (nodes.empty()) {
        int deepest = 0;
        std::vector<std::pair<uint32_t, int>> stack;
        if (!wideNodes.empty()) {
            stack.push_back({0u, 1});
        }
        while (!stack.empty()) {
            const auto [index, level] = stack.back();
            stack.pop_back();
            deepest = std::max(deepest, level);
            for (const uint32_t child : wideNodes[index].child) {
                if (child != kWideEmpty && (child & kWideLeafFlag) == 0) {
                    stack.push_back({child, level + 1});
                }
            }
        }
        return deepest;
    }
    int deepest = 0;
    std::vector<std::pair<uint32_t, int>> stack{{0u, 1}};
    while (!stack.empty()) {
        const auto [index, level] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, level);
        if (!nodes[index].isLeaf()) {
            stack.push_back({nodes[index].index, level + 1});
            stack.push_back({nodes[index].index + 1, level + 1});
        }
    }
    return deepest;
}

} // namespace raylab
