// The top of the tree (SubtreeBuilder::buildTop), depth first: large nodes one at a time, each
// node's references binned and distributed to its children by chunks on the whole team; smaller
// ones in batches, several at a time, each whole on one thread.

#include "bvh/build/bvh_build_subtree.h"

#include <algorithm>
#include <numeric>

namespace raylab {

namespace {

// Nodes of fewer references are split whole on one thread, several at a time, rather than by
// chunks on the team: below one and a half chunks' worth (where each of its four chunks would
// hold fewer than 6,144 references), a node's parallel loops are short enough that the team's
// threads spend much of them waking and waiting; above it, a node split whole can hold up its
// batch (the thin triangles' first batch is two nodes of about 30,000 references, one taking
// twice as long as the other). Measured on the Zen 5, 2 threads (PERFORMANCE.md, "What each
// change gained: the BVH build").
constexpr uint32_t kWholeBelow = kBuildChunkSize * 3 / 2;
// Such nodes are split in batches of this many (fewer when no other node is waiting), taken in
// depth-first order; a rule of the counts alone, so that the slots do not depend on the team.
constexpr std::size_t kBatch = 8;

} // namespace

SplitKind SubtreeBuilder::splitOnTeam(const BuildTask& task, BuildTeam& team, BinSet& scratch,
                                      std::vector<BinSet>& chunkBins, BuildTask& left,
                                      BuildTask& right) const {
    const uint32_t count = task.count;
    const SplitChoice choice = choose(task.first, count, task.bounds, task.depth, task.splitBudget,
                                      &team, scratch, chunkBins);
    const BuildChunks cut(count);
    const std::size_t chunks = cut.count;
    const auto chunkBegin = [&](std::size_t i) { return task.first + cut.begin(i); };
    const auto chunkEnd = [&](std::size_t i) { return task.first + cut.end(i); };
    SplitKind kind = choice.kind;
    if (kind == SplitKind::Spatial) {
        // Counted first, chunk by chunk, and written only if kept, each chunk's parts straight
        // to their places: cutting the crossing references twice costs less than writing every
        // part aside and copying it (which took 700 of Sponza's first build's page faults).
        std::vector<SpatialSides> made(chunks);
        std::vector<RecordBounds> leftBounds(chunks), rightBounds(chunks);
        team.forEach(chunks, [&](std::size_t i) {
            RecordBounds lb, rb; // stored once: the chunks' bounds lie side by side
            made[i] = countSpatialSplit(*context_.scene, chunkBegin(i), chunkEnd(i), choice.spatial,
                                        context_.slack, lb, rb);
            leftBounds[i] = lb;
            rightBounds[i] = rb;
        });
        std::vector<std::size_t> leftAt(chunks), rightAt(chunks);
        std::size_t leftSize = 0, rightSize = 0;
        for (std::size_t i = 0; i < chunks; ++i) {
            leftAt[i] = leftSize;
            rightAt[i] = rightSize;
            leftSize += made[i].left;
            rightSize += made[i].right;
            left.bounds.merge(leftBounds[i]);
            right.bounds.merge(rightBounds[i]);
        }
        if (keepsSpatialSplit(choice, count, task.splitBudget, context_.minGainPerReference,
                              leftSize, left.bounds, rightSize, right.bounds)) {
            // Each side in chunk order to its room in the parent's spare room.
            placeChildren(task, leftSize, rightSize, task.spare, task.first, left, right);
            team.forEach(chunks, [&](std::size_t i) {
                RecordBounds lb, rb; // counted above
                applySpatialSplit(*context_.scene, chunkBegin(i), chunkEnd(i), choice.spatial,
                                  context_.slack, left.first + leftAt[i], right.first + rightAt[i],
                                  lb, rb);
            });
            return kind;
        }
        kind = choice.fallback;
        left.bounds = right.bounds = RecordBounds{};
    }
    if (kind == SplitKind::Object) {
        // Each chunk's references go to their places in the spare room (offsets from the
        // chunks' bins), in the order of the parent; the parent's room becomes the spare.
        placeChildren(task, choice.object.leftCount, count - choice.object.leftCount, task.spare,
                      task.first, left, right);
        std::vector<std::size_t> leftAt(chunks), rightAt(chunks);
        std::size_t l = 0, r = 0;
        for (std::size_t i = 0; i < chunks; ++i) {
            leftAt[i] = l;
            rightAt[i] = r;
            const uint32_t n =
                chunks == 1 ? choice.object.leftCount : leftCountOf(chunkBins[i], choice.object);
            l += n;
            r += static_cast<std::size_t>(chunkEnd(i) - chunkBegin(i)) - n;
        }
        std::vector<RecordBounds> leftBounds(chunks), rightBounds(chunks);
        team.forEach(chunks, [&](std::size_t i) {
            RecordBounds lb, rb; // stored once, as above
            partitionRecords(chunkBegin(i), chunkEnd(i), choice.object, left.first + leftAt[i],
                             right.first + rightAt[i], lb, rb);
            leftBounds[i] = lb;
            rightBounds[i] = rb;
        });
        for (std::size_t i = 0; i < chunks; ++i) {
            left.bounds.merge(leftBounds[i]);
            right.bounds.merge(rightBounds[i]);
        }
    } else if (kind == SplitKind::Median) {
        splitAtMedian(task, left, right);
    }
    return kind;
}

void SubtreeBuilder::buildTop(Subtree& out, BuildTask root, BuildTeam& team, std::size_t deferBelow,
                              std::vector<BuildTask>& deferred) const {
    // What became of one node of a batch: its split (Leaf: none) and children.
    struct NodeSplit {
        SplitKind kind = SplitKind::Leaf;
        BuildTask left, right;
    };
    std::vector<BuildTask> stack{root}, batch;
    std::vector<NodeSplit> splits;
    std::vector<std::size_t> order; // the batch's nodes, largest first
    BinSet scratch;
    std::vector<BinSet> chunkBins;
    while (!stack.empty() || !batch.empty()) {
        if (!stack.empty()) {
            const BuildTask task = stack.back();
            stack.pop_back();
            if (task.count <= deferBelow && task.count > static_cast<uint32_t>(maxLeaf_)) {
                // Not a leaf, until its subtree's root takes the slot (bvh_build.cpp, assemble).
                out.nodes[task.slot] = BvhNode{};
                deferred.push_back(task);
                continue;
            }
            const Aabb box = task.bounds.box.toAabb();
            out.nodes[task.slot].lower = box.lower;
            out.nodes[task.slot].upper = box.upper;
            if (task.count >= kWholeBelow) {
                BuildTask left, right;
                if (splitOnTeam(task, team, scratch, chunkBins, left, right) == SplitKind::Leaf) {
                    out.addLeaf(task.slot, task.first, task.count);
                } else {
                    splitIntoChildren(task, left, right, out, stack);
                }
                continue;
            }
            batch.push_back(task);
            if (batch.size() < kBatch && !stack.empty()) {
                continue;
            }
        }
        splits.assign(batch.size(), NodeSplit{});
        order.resize(batch.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return batch[a].count > batch[b].count;
        });
        team.forEach(order.size(), [&](std::size_t k) {
            const std::size_t i = order[k];
            BinSet own; // the job's: the batch's nodes run side by side
            NodeSplit s;
            s.kind = splitNode(batch[i], own, s.left, s.right);
            splits[i] = s;
        });
        // Children's slots in the batch's order, whatever ran where.
        for (std::size_t i = 0; i < batch.size(); ++i) {
            if (splits[i].kind == SplitKind::Leaf) {
                out.addLeaf(batch[i].slot, batch[i].first, batch[i].count);
            } else {
                splitIntoChildren(batch[i], splits[i].left, splits[i].right, out, stack);
            }
        }
        batch.clear();
    }
}

} // namespace raylab
