// Binned SAH build of the binary BVH (bvh.h).
//
// Every valid triangle becomes a primitive record (its box and scene index). Nodes are split by
// the surface area heuristic evaluated at the borders of 16 bins over the centroids' extent on
// each axis (object splits), or, where the children of the best object split overlap, by a plane
// that cuts the triangles crossing it (spatial splits, bvh_spatial_split.h), within a budget of
// extra references. Each task owns its references; a last pass orders the leaves' references
// so that every subtree's are contiguous. The top of the tree is built on the calling
// thread until subtrees are small (a size threshold that depends only on the triangle count);
// those subtrees are then built in parallel into their own node arrays and appended in a fixed
// order, so the result is the same whatever the thread count.

#include "bvh.h"
#include "bvh_binning.h"
#include "bvh_collapse.h"
#include "bvh_presplit.h"
#include "bvh_spatial_split.h"
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

// The references of a subtree waiting to become the node at nodes[slot].
struct BuildTask {
    uint32_t slot = 0;
    std::vector<PrimRecord> records;
    int depth = 0;
    uint32_t splitBudget = 0; // extra references its spatial splits may still make
};

// What the build needs besides the references.
struct BuildContext {
    const Scene* scene = nullptr;
    float slack = 0.0f;          // splitBox's (bvh_clip.h)
    float minOverlapArea = 0.0f; // spatial splits only where object splits overlap more
    float minNodeOverlap = 0.0f; // ... and more than this fraction of the node's own surface
};

// A built subtree: nodes[0] is its root; leaf node i holds records [index, index + count).
struct Subtree {
    std::vector<BvhNode> nodes;
    std::vector<PrimRecord> records;
};

// Builds subtrees. Children of a split are appended as a pair.
class Builder {
public:
    Builder(const BvhBuildOptions& options, const BuildContext& context)
        : maxLeaf_(std::clamp(options.maxLeafSize, 1, kMaxLeafSize)),
          bins_(std::clamp(options.binCount, 2, kMaxBins)), context_(context) {}

    // Builds the subtree of `root` into out (root at out.nodes[root.slot]); stops descending
    // (and records the task in `deferred` instead) at nodes with no more than `deferBelow`
    // references, when that is > 0.
    void build(Subtree& out, BuildTask root, std::size_t deferBelow,
               std::vector<BuildTask>* deferred) const {
        std::vector<BuildTask> stack;
        stack.push_back(std::move(root));
        std::vector<PrimRecord> left, right;
        while (!stack.empty()) {
            BuildTask task = std::move(stack.back());
            stack.pop_back();
            const std::size_t count = task.records.size();
            if (deferred && count <= deferBelow && count > static_cast<std::size_t>(maxLeaf_)) {
                deferred->push_back(std::move(task));
                continue;
            }
            Aabb bounds, centroids;
            boundsOf(task.records.data(), task.records.data() + count, bounds, centroids);
            BvhNode& node = out.nodes[task.slot];
            node.lower = bounds.lower;
            node.upper = bounds.upper;
            if (!chooseSplit(task, bounds, centroids, left, right)) { // leaf
                node.index = static_cast<uint32_t>(out.records.size());
                node.count = static_cast<uint32_t>(count);
                out.records.insert(out.records.end(), task.records.begin(), task.records.end());
                continue;
            }
            const auto first = static_cast<uint32_t>(out.nodes.size());
            out.nodes.resize(out.nodes.size() + 2);
            out.nodes[task.slot].index = first; // `node` may dangle after the resize
            out.nodes[task.slot].count = 0;
            // The budget left after this split goes to the children by their sizes.
            const std::size_t made = left.size() + right.size() - count;
            const uint64_t budget = task.splitBudget - std::min<uint64_t>(task.splitBudget, made);
            const auto leftBudget =
                static_cast<uint32_t>(budget * left.size() / (left.size() + right.size()));
            // Right first on the stack, so the left child's subtree follows it in memory.
            stack.push_back({first + 1, std::move(right), task.depth + 1,
                             static_cast<uint32_t>(budget) - leftBudget});
            stack.push_back({first, std::move(left), task.depth + 1, leftBudget});
            left = {};
            right = {};
        }
    }

private:
    // The best object split (binned SAH over centroids) of a task.
    struct ObjectSplit {
        int axis = -1;
        int bin = 0;
        float cost = kInfinity;
        float overlapArea = 0.0f; // surface of the intersection of the children's boxes
        glm::vec3 scale{0.0f};
    };

    // Splits the task's references into left and right, or returns false for a leaf.
    bool chooseSplit(BuildTask& task, const Aabb& bounds, const Aabb& centroids,
                     std::vector<PrimRecord>& left, std::vector<PrimRecord>& right) const {
        std::vector<PrimRecord>& records = task.records;
        const auto count = static_cast<uint32_t>(records.size());
        const glm::vec3 extent = centroids.upper - centroids.lower;
        const bool mustSplit = count > static_cast<uint32_t>(maxLeaf_);
        if (count <= 1) {
            return false;
        }
        const bool flat = !(extent.x > 0.0f) && !(extent.y > 0.0f) && !(extent.z > 0.0f);
        if (flat || task.depth >= kSahDepthLimit) {
            return mustSplit && medianSplit(records, extent, left, right);
        }
        const ObjectSplit object = findObjectSplit(records, centroids);
        float bestCost = object.cost;
        SpatialSplit spatial;
        if (task.splitBudget > 0 && context_.scene &&
            object.overlapArea > context_.minOverlapArea &&
            object.overlapArea > context_.minNodeOverlap * bounds.area()) {
            spatial = findSpatialSplit(*context_.scene, records, bounds, context_.slack);
            if (spatial.cost < bestCost && spatial.references - count <= task.splitBudget) {
                bestCost = spatial.cost;
            } else {
                spatial.axis = -1;
            }
        }
        if (object.axis < 0 && spatial.axis < 0) {
            return mustSplit && medianSplit(records, extent, left, right);
        }
        const float area = bounds.area();
        const float splitCost = kTraversalCost * area + bestCost;
        const float leafCost = static_cast<float>(count) * area;
        if (!mustSplit && leafCost <= splitCost) {
            return false;
        }
        // The bins estimate the references a spatial split makes; rounding at the plane may
        // make a few more, so the budget is checked again on the real split.
        if (spatial.axis >= 0 &&
            applySpatialSplit(*context_.scene, records, spatial, context_.slack, left, right) &&
            left.size() + right.size() - count <= task.splitBudget) {
            return true;
        }
        if (object.axis < 0) {
            return mustSplit && medianSplit(records, extent, left, right);
        }
        const int a = object.axis;
        const float lower = centroids.lower[a], s = object.scale[a];
        const auto middle =
            std::partition(records.begin(), records.end(), [&](const PrimRecord& r) {
                return binOf(r.centroid()[a], lower, s, bins_) < object.bin;
            });
        left.assign(records.begin(), middle);
        right.assign(middle, records.end());
        return true;
    }

    ObjectSplit findObjectSplit(const std::vector<PrimRecord>& records,
                                const Aabb& centroids) const {
        const auto count = static_cast<uint32_t>(records.size());
        const glm::vec3 extent = centroids.upper - centroids.lower;
        ObjectSplit best;
        BinSet bins;
        for (int a = 0; a < 3; ++a) {
            // Slightly below bins/extent so the largest centroid lands in the last bin.
            best.scale[a] =
                extent[a] > 0.0f ? static_cast<float>(bins_) * 0.99999f / extent[a] : 0.0f;
        }
        binRecords(records.data(), records.data() + count, centroids.lower, best.scale, bins_,
                   bins);
        // Sweep each axis: cost of splitting before bin s = A(left) N(left) + A(right) N(right).
        for (int a = 0; a < 3; ++a) {
            if (!(extent[a] > 0.0f)) {
                continue;
            }
            std::array<float, kMaxBins> rightCost{};
            std::array<Aabb, kMaxBins> rightBox{};
            Aabb box;
            uint32_t n = 0;
            for (int s = bins_ - 1; s > 0; --s) {
                box.extend(bins.box[a][s].toAabb());
                n += bins.count[a][s];
                rightCost[s] = box.area() * static_cast<float>(n);
                rightBox[s] = box;
            }
            box = Aabb{};
            n = 0;
            for (int s = 1; s < bins_; ++s) {
                box.extend(bins.box[a][s - 1].toAabb());
                n += bins.count[a][s - 1];
                const float cost = box.area() * static_cast<float>(n) + rightCost[s];
                if (n > 0 && n < count && cost < best.cost) {
                    best.cost = cost;
                    best.axis = a;
                    best.bin = s;
                    const Aabb overlap{glm::max(box.lower, rightBox[s].lower),
                                       glm::min(box.upper, rightBox[s].upper)};
                    best.overlapArea = overlap.area();
                }
            }
        }
        return best;
    }

    // Splits at the median record along the axis of the largest centroid extent (or in the
    // middle of the range when all centroids coincide). Always gives two non-empty halves.
    bool medianSplit(std::vector<PrimRecord>& records, const glm::vec3& extent,
                     std::vector<PrimRecord>& left, std::vector<PrimRecord>& right) const {
        const std::size_t mid = records.size() / 2;
        const int axis =
            extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
        if (extent[axis] > 0.0f) {
            std::nth_element(records.begin(), records.begin() + static_cast<std::ptrdiff_t>(mid),
                             records.end(), [axis](const PrimRecord& a, const PrimRecord& b) {
                                 const float ca = a.centroid()[axis], cb = b.centroid()[axis];
                                 return ca < cb || (ca == cb && a.sceneIndex < b.sceneIndex);
                             });
        }
        left.assign(records.begin(), records.begin() + static_cast<std::ptrdiff_t>(mid));
        right.assign(records.begin() + static_cast<std::ptrdiff_t>(mid), records.end());
        return true;
    }

    int maxLeaf_;
    int bins_;
    BuildContext context_;
};

// Appends `sub` (a subtree whose root is sub.nodes[0]) to `out`: the root goes to
// out.nodes[slot], the rest at the end, with child and leaf indices moved accordingly.
void appendSubtree(Subtree& out, uint32_t slot, const Subtree& sub) {
    const auto offset = static_cast<uint32_t>(out.nodes.size()) - 1; // local 1 -> nodes.size()
    const auto recordOffset = static_cast<uint32_t>(out.records.size());
    for (std::size_t i = 0; i < sub.nodes.size(); ++i) {
        BvhNode node = sub.nodes[i];
        node.index += node.isLeaf() ? recordOffset : offset;
        if (i == 0) {
            out.nodes[slot] = node;
        } else {
            out.nodes.push_back(node);
        }
    }
    out.records.insert(out.records.end(), sub.records.begin(), sub.records.end());
}

// Reorders the records so that every subtree's leaves are one contiguous range, left subtree
// first (the order the 8-wide collapse relies on), and points the leaves at it.
void orderLeaves(Subtree& tree) {
    std::vector<PrimRecord> ordered;
    ordered.reserve(tree.records.size());
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
        BvhNode& node = tree.nodes[stack.back()];
        stack.pop_back();
        if (node.isLeaf()) {
            const auto first = static_cast<uint32_t>(ordered.size());
            ordered.insert(ordered.end(), tree.records.begin() + node.index,
                           tree.records.begin() + node.index + node.count);
            node.index = first;
        } else {
            stack.push_back(node.index + 1);
            stack.push_back(node.index);
        }
    }
    tree.records.swap(ordered);
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
    const float slack = std::ldexp(std::max(magnitude, 1e-30f), -21);
    presplitRecords(scene, options.presplitBudget, slack, records);
    BuildContext context;
    if (options.spatialSplitBudget > 0.0f) {
        Aabb all, centres;
        boundsOf(records.data(), records.data() + records.size(), all, centres);
        context.scene = &scene;
        context.slack = slack;
        context.minOverlapArea = options.spatialSplitOverlap * all.area();
        context.minNodeOverlap = options.spatialSplitNodeOverlap;
    }
    const Builder builder(options, context);
    const std::size_t total = records.size();
    Subtree tree;
    tree.nodes.reserve(2 * total);
    tree.nodes.resize(1);
    std::vector<BuildTask> deferred;
    const std::size_t deferBelow = std::max(kMinTaskSize, total / 64);
    BuildTask root{0, std::move(records), 0, 0};
    root.splitBudget = static_cast<uint32_t>(
        std::min(1e9, static_cast<double>(std::max(0.0f, options.spatialSplitBudget)) *
                          static_cast<double>(total)));
    builder.build(tree, std::move(root), deferBelow, &deferred);

    // The small subtrees, each into its own arrays, handed out to threads by an atomic counter.
    std::vector<Subtree> subtrees(deferred.size());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < deferred.size();) {
            BuildTask local = std::move(deferred[i]);
            local.slot = 0;
            subtrees[i].nodes.reserve(local.records.size() + 1);
            subtrees[i].nodes.resize(1);
            builder.build(subtrees[i], std::move(local), 0, nullptr);
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
        appendSubtree(tree, deferred[i].slot, subtrees[i]);
    }
    orderLeaves(tree);
    records.swap(tree.records);
    bvh.nodes.swap(tree.nodes);
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
