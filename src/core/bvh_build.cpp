// Binned SAH build of the binary BVH (bvh.h).
//
// Every valid triangle becomes a primitive record (its box and scene index). Nodes are split by
// the surface area heuristic evaluated at the borders of 16 bins over the centroids' extent on
// each axis; records are partitioned in place, so every subtree owns a contiguous range of them
// and the final record order is the leaf order. The top of the tree is built on the calling
// thread until subtrees are small (a size threshold that depends only on the triangle count);
// those subtrees are then built in parallel into their own node arrays and appended in a fixed
// order, so the result is the same whatever the thread count.

#include "bvh.h"
#include "bvh_binning.h"
#include "bvh_collapse.h"
#include "bvh_presplit.h"
#include "parallel_tiles.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

namespace raylab {

namespace {

constexpr int kMaxLeafSize = 64;       // cap on BvhBuildOptions::maxLeafSize
constexpr int kSahDepthLimit = 40;     // deeper than this, nodes split at the median (depth bound)
constexpr float kTraversalCost = 1.0f; // SAH: one node visit, in units of one triangle test
constexpr std::size_t kMinTaskSize = 4096; // smallest subtree worth a parallel task

// A range of records waiting to become the node at nodes[slot].
struct BuildTask {
    uint32_t slot;
    uint32_t begin, end;
    int depth;
};

// Builds subtrees of one node array. Children of a split are appended as a pair.
class Builder {
public:
    Builder(std::vector<PrimRecord>& records, const BvhBuildOptions& options)
        : records_(records), maxLeaf_(std::clamp(options.maxLeafSize, 1, kMaxLeafSize)),
          bins_(std::clamp(options.binCount, 2, kMaxBins)) {}

    // Builds the subtree of `task` into nodes; stops descending (and records the task in
    // `deferred` instead) at nodes with no more than `deferBelow` records, when that is > 0.
    void build(std::vector<BvhNode>& nodes, BuildTask root, std::size_t deferBelow,
               std::vector<BuildTask>* deferred) const {
        std::vector<BuildTask> stack{root};
        while (!stack.empty()) {
            const BuildTask task = stack.back();
            stack.pop_back();
            const std::size_t count = task.end - task.begin;
            if (deferred && count <= deferBelow && count > static_cast<std::size_t>(maxLeaf_)) {
                deferred->push_back(task);
                continue;
            }
            Aabb bounds, centroids;
            boundsOf(records_.data() + task.begin, records_.data() + task.end, bounds, centroids);
            BvhNode& node = nodes[task.slot];
            node.lower = bounds.lower;
            node.upper = bounds.upper;
            const uint32_t mid = chooseSplit(task, bounds, centroids);
            if (mid == task.begin) { // leaf
                node.index = task.begin;
                node.count = static_cast<uint32_t>(count);
                continue;
            }
            const auto first = static_cast<uint32_t>(nodes.size());
            nodes.resize(nodes.size() + 2);
            nodes[task.slot].index = first; // `node` may dangle after the resize
            nodes[task.slot].count = 0;
            // Right first on the stack, so the left child's subtree follows it in memory.
            stack.push_back({first + 1, mid, task.end, task.depth + 1});
            stack.push_back({first, task.begin, mid, task.depth + 1});
        }
    }

private:
    // Partitions the task's records and returns the first record of the right child, or
    // task.begin when the node should be a leaf.
    uint32_t chooseSplit(const BuildTask& task, const Aabb& bounds, const Aabb& centroids) const {
        const uint32_t count = task.end - task.begin;
        const glm::vec3 extent = centroids.upper - centroids.lower;
        const bool mustSplit = count > static_cast<uint32_t>(maxLeaf_);
        if (count <= 1) {
            return task.begin;
        }
        const bool flat = !(extent.x > 0.0f) && !(extent.y > 0.0f) && !(extent.z > 0.0f);
        if (flat || task.depth >= kSahDepthLimit) {
            return mustSplit ? medianSplit(task, extent) : task.begin;
        }

        BinSet bins;
        glm::vec3 scale;
        for (int a = 0; a < 3; ++a) {
            // Slightly below bins/extent so the largest centroid lands in the last bin.
            scale[a] = extent[a] > 0.0f ? static_cast<float>(bins_) * 0.99999f / extent[a] : 0.0f;
        }
        binRecords(records_.data() + task.begin, records_.data() + task.end, centroids.lower, scale,
                   bins_, bins);

        // Sweep each axis: cost of splitting before bin s = A(left) N(left) + A(right) N(right).
        float bestCost = kInfinity;
        int bestAxis = -1, bestSplit = 0;
        for (int a = 0; a < 3; ++a) {
            if (!(extent[a] > 0.0f)) {
                continue;
            }
            std::array<float, kMaxBins> rightCost{};
            Aabb box;
            uint32_t n = 0;
            for (int s = bins_ - 1; s > 0; --s) {
                box.extend(bins.box[a][s].toAabb());
                n += bins.count[a][s];
                rightCost[s] = box.area() * static_cast<float>(n);
            }
            box = Aabb{};
            n = 0;
            for (int s = 1; s < bins_; ++s) {
                box.extend(bins.box[a][s - 1].toAabb());
                n += bins.count[a][s - 1];
                const float cost = box.area() * static_cast<float>(n) + rightCost[s];
                if (n > 0 && n < count && cost < bestCost) {
                    bestCost = cost;
                    bestAxis = a;
                    bestSplit = s;
                }
            }
        }
        if (bestAxis < 0) {
            return mustSplit ? medianSplit(task, extent) : task.begin;
        }
        const float area = bounds.area();
        const float splitCost = kTraversalCost * area + bestCost;
        const float leafCost = static_cast<float>(count) * area;
        if (!mustSplit && leafCost <= splitCost) {
            return task.begin;
        }
        const float lower = centroids.lower[bestAxis], s = scale[bestAxis];
        const auto middle = std::partition(
            records_.begin() + task.begin, records_.begin() + task.end, [&](const PrimRecord& r) {
                return binOf(r.centroid()[bestAxis], lower, s, bins_) < bestSplit;
            });
        return static_cast<uint32_t>(middle - records_.begin());
    }

    // Splits at the median record along the axis of the largest centroid extent (or in the
    // middle of the range when all centroids coincide). Always gives two non-empty halves.
    uint32_t medianSplit(const BuildTask& task, const glm::vec3& extent) const {
        const uint32_t mid = task.begin + (task.end - task.begin) / 2;
        const int axis =
            extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
        if (extent[axis] > 0.0f) {
            std::nth_element(records_.begin() + task.begin, records_.begin() + mid,
                             records_.begin() + task.end,
                             [axis](const PrimRecord& a, const PrimRecord& b) {
                                 const float ca = a.centroid()[axis], cb = b.centroid()[axis];
                                 return ca < cb || (ca == cb && a.sceneIndex < b.sceneIndex);
                             });
        }
        return mid;
    }

    std::vector<PrimRecord>& records_;
    int maxLeaf_;
    int bins_;
};

// Appends `sub` (a subtree whose root is sub[0]) to nodes: the root goes to nodes[slot], the rest
// at the end, with child indices moved accordingly.
void appendSubtree(std::vector<BvhNode>& nodes, uint32_t slot, const std::vector<BvhNode>& sub) {
    const auto offset = static_cast<uint32_t>(nodes.size()) - 1; // local 1 -> nodes.size()
    for (std::size_t i = 0; i < sub.size(); ++i) {
        BvhNode node = sub[i];
        if (!node.isLeaf()) {
            node.index += offset;
        }
        if (i == 0) {
            nodes[slot] = node;
        } else {
            nodes.push_back(node);
        }
    }
}

// Widens every node box by `pad` (world units) so that box tests, done in rounded float
// arithmetic, never cull a triangle the watertight test hits.
void padBounds(std::vector<BvhNode>& nodes, float pad) {
    for (BvhNode& node : nodes) {
        node.lower -= glm::vec3(pad);
        node.upper += glm::vec3(pad);
    }
}

} // namespace

Bvh buildBvh(const Scene& scene, const BvhBuildOptions& options) {
    Bvh bvh;
    std::vector<PrimRecord> records;
    records.reserve(scene.triangles.size());
    float magnitude = 0.0f; // largest |coordinate| of a valid vertex
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        if (!isValidTriangle(t)) {
            ++bvh.skippedTriangles;
            continue;
        }
        const glm::vec3 lower = glm::min(t.v0, glm::min(t.v1, t.v2));
        const glm::vec3 upper = glm::max(t.v0, glm::max(t.v1, t.v2));
        magnitude = std::max({magnitude, glm::abs(lower).x, glm::abs(lower).y, glm::abs(lower).z,
                              glm::abs(upper).x, glm::abs(upper).y, glm::abs(upper).z});
        records.push_back({lower, static_cast<uint32_t>(i), upper});
    }
    if (records.empty()) {
        return bvh;
    }

    // Split boxes are widened by 2^-21 of the largest coordinate (several ulps of any vertex
    // coordinate), and node boxes by 2^-19 below.
    presplitRecords(scene, options.presplitBudget, std::ldexp(std::max(magnitude, 1e-30f), -21),
                    records);
    const Builder builder(records, options);
    const auto total = static_cast<uint32_t>(records.size());
    bvh.nodes.reserve(2 * records.size());
    bvh.nodes.resize(1);
    std::vector<BuildTask> deferred;
    const std::size_t deferBelow = std::max(kMinTaskSize, records.size() / 64);
    builder.build(bvh.nodes, BuildTask{0, 0, total, 0}, deferBelow, &deferred);

    // The small subtrees, each into its own array, handed out to threads by an atomic counter.
    std::vector<std::vector<BvhNode>> subtrees(deferred.size());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < deferred.size();) {
            BuildTask local = deferred[i];
            local.slot = 0;
            subtrees[i].reserve(2 * (local.end - local.begin) / 2 + 1);
            subtrees[i].resize(1);
            builder.build(subtrees[i], local, 0, nullptr);
        }
    };
    const int threads = std::min<int>(resolveThreadCount(options.threads),
                                      static_cast<int>(std::max<std::size_t>(1, deferred.size())));
    {
        std::vector<std::jthread> helpers;
        for (int i = 1; i < threads; ++i) {
            helpers.emplace_back(work);
        }
        work();
    }
    for (std::size_t i = 0; i < deferred.size(); ++i) {
        appendSubtree(bvh.nodes, deferred[i].slot, subtrees[i]);
    }
    bvh.nodes.shrink_to_fit();

    // Box tests round; the watertight test's edge decisions round too. 2^-19 of the scene's
    // largest coordinate is far above both errors and far below any visible size.
    padBounds(bvh.nodes, std::ldexp(std::max(magnitude, 1e-30f), -19));

    bvh.leafReferences = records.size();
    bvh.triangles.resize(records.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
        const Triangle& t = scene.triangles[records[i].sceneIndex];
        bvh.triangles[i] = BvhTriangle{t.v0, t.v1, t.v2, records[i].sceneIndex};
    }
    if (options.simd && bvhSimdSupported()) {
        buildWideBvh(bvh);
    }
    return bvh;
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

int Bvh::depth() const {
    if (nodes.empty()) {
        return 0;
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
