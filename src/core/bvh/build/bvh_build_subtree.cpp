#include "bvh/build/bvh_build_subtree.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

constexpr int kMaxLeafSize = 64;       // cap on BvhBuildOptions::maxLeafSize
constexpr int kSahDepthLimit = 40;     // deeper than this, nodes split at the median (depth bound)
constexpr float kTraversalCost = 1.0f; // SAH: one node visit, in units of one triangle test
// Spatial splits are tried only where the references reach beyond their object bins by this
// much (binOverreach): where they are small against the node, its overlap comes from the
// shape of the surface, which cutting triangles does not remove (the dragon's large nodes).
constexpr float kMinSpatialOverreach = 1.0f;
// Spatial splits are not tried at nodes of fewer references: there a try costs a large share of
// the node's work and rarely wins (the thin triangles' build 12% fewer instructions, their rays'
// work the same; PERFORMANCE.md, "What each change gained: the BVH build").
constexpr uint32_t kMinSpatialCount = 64;
// Nor at nodes whose split budget is under a kMinSpatialBudgetPer-th of their references: a cut
// across such a node rarely fits in its budget, and as the budget is shared by size, its whole
// subtree tries none. The thin triangles' nodes reach it once the top levels' splits have used
// most of the budget: 9 of their 1,716 tries below it won, Sponza's 4 of 34; without them the
// thin triangles' build takes 13% fewer instructions and their rays trace as fast
// (PERFORMANCE.md, "What each change gained: the BVH build").
constexpr uint64_t kMinSpatialBudgetPer = 20; // budget * 20 >= references
// Nodes of more than kSpatialSampleFrom references bin a sample of at least kSpatialSample of
// them for their spatial split (every count / kSpatialSample-th reference); the split is then
// checked on the references it makes (keepsSpatialSplit). PERFORMANCE.md, "What each change gained:
// the BVH build".
constexpr uint32_t kSpatialSampleFrom = 2048;
constexpr uint32_t kSpatialSample = 1024;

// Runs job(i) for i in [0, count): on the team when there is one.
template <typename Job> void forEachChunk(std::size_t count, BuildTeam* team, const Job& job) {
    if (count == 1 || !team) {
        for (std::size_t i = 0; i < count; ++i) {
            job(i);
        }
        return;
    }
    team->forEach(count, job);
}

// Whether a spatial split of SAH cost `cost` that makes `references` of a node's `count` lowers
// the cost of the node's object split (which must exist) by at least minGain times the
// fraction of references it adds (BvhBuildOptions::spatialSplitMinGain).
bool gainsEnough(const ObjectSplit& object, float cost, uint32_t count, std::size_t references,
                 float minGain) {
    if (!(minGain > 0.0f)) {
        return true; // no gain asked for
    }
    const double gain = static_cast<double>(object.cost) - cost;
    const double added = static_cast<double>(references) - count;
    return gain * count >= static_cast<double>(minGain) * object.cost * added;
}

} // namespace

SubtreeBuilder::SubtreeBuilder(const BvhBuildOptions& options, const BuildContext& context)
    : maxLeaf_(std::clamp(options.maxLeafSize, 1, kMaxLeafSize)),
      bins_(std::clamp(options.binCount, 2, kMaxBins)), context_(context) {}

SplitChoice SubtreeBuilder::choose(const PrimRecord* first, uint32_t count,
                                   const RecordBounds& nodeBounds, int depth, uint32_t splitBudget,
                                   BuildTeam* team, BinSet& scratch,
                                   std::vector<BinSet>& chunkBins) const {
    SplitChoice choice;
    if (count <= 1 || count <= context_.leafAtMost) {
        return choice;
    }
    const bool mustSplit = count > static_cast<uint32_t>(maxLeaf_);
    const SplitKind orMedian = mustSplit ? SplitKind::Median : SplitKind::Leaf;
    const Aabb bounds = nodeBounds.box.toAabb();
    const Aabb centroids = nodeBounds.centres.toAabb();
    const glm::vec3 extent = centroids.upper - centroids.lower;
    const bool flat = !(extent.x > 0.0f) && !(extent.y > 0.0f) && !(extent.z > 0.0f);
    if (flat || depth >= kSahDepthLimit) {
        choice.kind = orMedian;
        return choice;
    }
    const BuildChunks cut(count);
    const std::size_t chunks = team ? cut.count : 1;
    auto chunkBegin = [&](std::size_t i) { return chunks == 1 ? first : first + cut.begin(i); };
    auto chunkEnd = [&](std::size_t i) { return chunks == 1 ? first + count : first + cut.end(i); };

    // The best object split, from the bins of every chunk merged in chunk order.
    // As many bins for small nodes as for large ones: fewer (4 plus one per 20 references, as
    // Embree's builder bins) build the dragon 7-12% faster but make the box's packets 25% slower.
    const int bins = bins_;
    const ObjectSplit frame = objectBinFrame(centroids, bins);
    chunkBins.resize(chunks > 1 ? chunks : 0);
    if (chunks > 1) {
        forEachChunk(chunks, team, [&](std::size_t i) {
            chunkBins[i].reset(bins);
            binRecords(chunkBegin(i), chunkEnd(i), frame.lower, frame.scale, bins, chunkBins[i]);
        });
        for (const BinSet& b : chunkBins) {
            scratch.merge(b, bins);
        }
    } else {
        binRecords(first, first + count, frame.lower, frame.scale, bins, scratch);
    }
    choice.object = bestObjectSplit(scratch, count, frame);

    // The best spatial split, where the object split's children overlap much, across the
    // object split's axis: the cut competes with that split where its children overlap.
    // Binning the other two axes as well took half of Sponza's build, and its trees traced
    // slower (PERFORMANCE.md, "What each change gained: the BVH build").
    const bool trySpatial = count >= kMinSpatialCount && splitBudget > 0 && context_.scene &&
                            uint64_t{splitBudget} * kMinSpatialBudgetPer >= count &&
                            choice.object.axis >= 0 &&
                            choice.object.overlapArea > context_.minOverlapArea &&
                            choice.object.overlapArea > context_.minNodeOverlap * bounds.area() &&
                            binOverreach(scratch, frame, bounds) >= kMinSpatialOverreach;
    scratch.clearUsed(bins);
    float bestCost = choice.object.cost;
    if (trySpatial) {
        const uint32_t stride = count > kSpatialSampleFrom ? count / kSpatialSample : 1;
        std::vector<SpatialBins> parts(chunks);
        forEachChunk(chunks, team, [&](std::size_t i) {
            // The chunk's samples: the references at multiples of stride in the node.
            const auto begin = static_cast<std::size_t>(chunkBegin(i) - first);
            const auto end = static_cast<std::size_t>(chunkEnd(i) - first);
            const std::size_t firstSample = std::min(end, (begin + stride - 1) / stride * stride);
            binSpatial(first + firstSample, first + end, bounds, choice.object.axis, parts[i],
                       stride);
        });
        for (std::size_t i = 1; i < parts.size(); ++i) {
            parts[0].merge(parts[i]);
        }
        choice.spatial = bestSpatialSplit(parts[0], bounds, choice.object.axis);
        if (stride > 1 && choice.spatial.axis >= 0) {
            const uint32_t samples = (count + stride - 1) / stride;
            const double toNode = static_cast<double>(count) / static_cast<double>(samples);
            choice.spatial.cost = static_cast<float>(choice.spatial.cost * toNode);
            choice.spatial.references = static_cast<uint32_t>(std::max(
                static_cast<double>(count), std::round(choice.spatial.references * toNode)));
            choice.spatial.sampled = true;
        }
        if (choice.spatial.cost < bestCost && choice.spatial.references - count <= splitBudget &&
            gainsEnough(choice.object, choice.spatial.cost, count, choice.spatial.references,
                        context_.minGainPerReference)) {
            bestCost = choice.spatial.cost;
        } else {
            choice.spatial.axis = -1;
        }
    }
    if (choice.object.axis < 0 && choice.spatial.axis < 0) {
        choice.kind = orMedian;
        return choice;
    }
    const float area = bounds.area();
    const float splitCost = kTraversalCost * area + bestCost;
    const float leafCost = static_cast<float>(count) * area;
    if (!mustSplit && leafCost <= splitCost) {
        return choice; // a leaf
    }
    // The bins estimate the references a spatial split makes; rounding at the plane may make a
    // few more, so the budget is checked again on the real split, falling back to the object
    // split.
    const SplitKind objectOrMedian = choice.object.axis >= 0 ? SplitKind::Object : orMedian;
    choice.kind = choice.spatial.axis >= 0 ? SplitKind::Spatial : objectOrMedian;
    choice.fallback = objectOrMedian;
    return choice;
}

SplitKind SubtreeBuilder::splitNode(const BuildTask& task, BinSet& scratch, BuildTask& left,
                                    BuildTask& right) const {
    std::vector<BinSet> noChunks; // never allocated: no team
    const SplitChoice choice = choose(task.first, task.count, task.bounds, task.depth,
                                      task.splitBudget, nullptr, scratch, noChunks);
    SplitKind kind = choice.kind;
    if (kind == SplitKind::Spatial) {
        // Both sides into the spare room, the right side from its end: where the right side goes
        // depends on the left side's size, and the split may yet fall back. A kept split's sides
        // fit the room (keepsSpatialSplit checks the budget).
        const SpatialSides made = applySpatialSplitInRoom(
            *context_.scene, task.first, task.first + task.count, choice.spatial, context_.slack,
            task.spare, task.room(), left.bounds, right.bounds);
        if (keepsSpatialSplit(choice, task.count, task.splitBudget, context_.minGainPerReference,
                              made.left, left.bounds, made.right, right.bounds)) {
            placeChildren(task, made.left, made.right, task.spare, task.first, left, right);
            // Down to the right child's room, which starts at or before it.
            const PrimRecord* rightSide = task.spare + (task.room() - made.right);
            std::copy(rightSide, rightSide + made.right, right.first);
            return kind;
        }
        kind = choice.fallback;
        left.bounds = right.bounds = RecordBounds{};
    }
    if (kind == SplitKind::Object) {
        // Into the spare room, which the children then own as their references; the parent's
        // room becomes their spare.
        placeChildren(task, choice.object.leftCount, task.count - choice.object.leftCount,
                      task.spare, task.first, left, right);
        partitionRecords(task.first, task.first + task.count, choice.object, left.first,
                         right.first, left.bounds, right.bounds);
    } else if (kind == SplitKind::Median) {
        splitAtMedian(task, left, right);
    }
    return kind;
}

void SubtreeBuilder::buildSubtree(Subtree& out, const BuildTask& root) const {
    std::vector<BuildTask> stack{root};
    BinSet scratch;
    while (!stack.empty()) {
        const BuildTask task = stack.back();
        stack.pop_back();
        const Aabb box = task.bounds.box.toAabb();
        out.nodes[task.slot].lower = box.lower;
        out.nodes[task.slot].upper = box.upper;
        BuildTask left, right;
        if (splitNode(task, scratch, left, right) == SplitKind::Leaf) {
            out.addLeaf(task.slot, task.first, task.count);
            continue;
        }
        splitIntoChildren(task, left, right, out, stack);
    }
}

bool keepsSpatialSplit(const SplitChoice& choice, uint32_t count, uint32_t splitBudget,
                       float minGainPerReference, std::size_t leftSize,
                       const RecordBounds& leftBounds, std::size_t rightSize,
                       const RecordBounds& rightBounds) {
    if (leftSize == 0 || rightSize == 0 || leftSize + rightSize - count > splitBudget) {
        return false;
    }
    if (choice.object.axis < 0) {
        return true; // no object split to compare with
    }
    const float cost = leftBounds.box.toAabb().area() * static_cast<float>(leftSize) +
                       rightBounds.box.toAabb().area() * static_cast<float>(rightSize);
    // Unsampled, the bins' cost is an upper bound of the split's (bvh_spatial_split.h).
    if (choice.spatial.sampled && !(cost < choice.object.cost)) {
        return false;
    }
    return gainsEnough(choice.object, cost, count, leftSize + rightSize, minGainPerReference);
}

void Subtree::addLeaf(uint32_t slot, const PrimRecord* first, uint32_t count) {
    nodes[slot].index = static_cast<uint32_t>(leafTriangles.size());
    nodes[slot].count = count;
    for (uint32_t i = 0; i < count; ++i) {
        leafTriangles.push_back(first[i].sceneIndex);
    }
}

void placeChildren(const BuildTask& task, std::size_t leftCount, std::size_t rightCount,
                   PrimRecord* to, PrimRecord* from, BuildTask& left, BuildTask& right) {
    left.count = static_cast<uint32_t>(leftCount);
    right.count = static_cast<uint32_t>(rightCount);
    const std::size_t sizes = leftCount + rightCount;
    const uint64_t budget =
        task.splitBudget - std::min<uint64_t>(task.splitBudget, sizes - task.count);
    left.splitBudget = static_cast<uint32_t>(budget * left.count / sizes);
    right.splitBudget = static_cast<uint32_t>(budget) - left.splitBudget;
    left.first = to;
    left.spare = from;
    right.first = to + left.room();
    right.spare = from + left.room();
}

void splitAtMedian(const BuildTask& task, BuildTask& left, BuildTask& right) {
    medianOrder(task.first, task.count, task.bounds);
    const uint32_t half = task.count / 2;
    placeChildren(task, half, task.count - half, task.first, task.spare, left, right);
    std::copy_backward(task.first + half, task.first + task.count, right.first + right.count);
    left.bounds = boundsOf(left.first, left.first + left.count);
    right.bounds = boundsOf(right.first, right.first + right.count);
}

void splitIntoChildren(const BuildTask& task, BuildTask left, BuildTask right, Subtree& out,
                       std::vector<BuildTask>& stack) {
    const auto first = static_cast<uint32_t>(out.nodes.size());
    out.nodes.resize(out.nodes.size() + 2);
    out.nodes[task.slot].index = first;
    out.nodes[task.slot].count = 0;
    left.slot = first;
    right.slot = first + 1;
    left.depth = right.depth = task.depth + 1;
    stack.push_back(right);
    stack.push_back(left);
}

} // namespace raylab
