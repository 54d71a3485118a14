// The top of the tree (SubtreeBuilder::buildTop): one node at a time, each node's references
// binned and distributed to its children by chunks on the whole team.

#include "bvh/build/bvh_build_subtree.h"

#include <algorithm>

namespace raylab {

void SubtreeBuilder::buildTop(Subtree& out, BuildTask root, BuildTeam& team, std::size_t deferBelow,
                              std::vector<BuildTask>& deferred) const {
    std::vector<BuildTask> stack{root};
    BinSet scratch;
    std::vector<BinSet> chunkBins;
    while (!stack.empty()) {
        const BuildTask task = stack.back();
        stack.pop_back();
        const uint32_t count = task.count;
        if (count <= deferBelow && count > static_cast<uint32_t>(maxLeaf_)) {
            deferred.push_back(task);
            continue;
        }
        const Aabb box = task.bounds.box.toAabb();
        out.nodes[task.slot].lower = box.lower;
        out.nodes[task.slot].upper = box.upper;
        const SplitChoice choice = choose(task.first, count, task.bounds, task.depth,
                                          task.splitBudget, &team, scratch, chunkBins);
        const BuildChunks cut(count);
        const std::size_t chunks = cut.count;
        const auto chunkBegin = [&](std::size_t i) { return task.first + cut.begin(i); };
        const auto chunkEnd = [&](std::size_t i) { return task.first + cut.end(i); };
        BuildTask left, right;
        SplitKind kind = choice.kind;
        if (kind == SplitKind::Spatial) {
            std::vector<RecordVector> lefts(chunks), rights(chunks);
            std::vector<RecordBounds> leftBounds(chunks), rightBounds(chunks);
            team.forEach(chunks, [&](std::size_t i) {
                // Into the job's own arrays and bounds, stored once: the chunks' vectors and
                // bounds lie side by side, and writing them record by record from several
                // threads made Sponza's top spatial splits 3-6 times slower on 2 threads.
                // A reference goes to one side, or is cut into at most one part on each.
                const auto size = static_cast<std::size_t>(chunkEnd(i) - chunkBegin(i));
                RecordVector l(size), r(size);
                RecordBounds lb, rb;
                const SpatialSides made =
                    applySpatialSplit(*context_.scene, chunkBegin(i), chunkEnd(i), choice.spatial,
                                      context_.slack, l.data(), r.data(), lb, rb);
                l.resize(made.left);
                r.resize(made.right);
                lefts[i] = std::move(l);
                rights[i] = std::move(r);
                leftBounds[i] = lb;
                rightBounds[i] = rb;
            });
            std::size_t leftSize = 0, rightSize = 0;
            for (std::size_t i = 0; i < chunks; ++i) {
                leftSize += lefts[i].size();
                rightSize += rights[i].size();
                left.bounds.merge(leftBounds[i]);
                right.bounds.merge(rightBounds[i]);
            }
            if (keepsSpatialSplit(choice, count, task.splitBudget, context_.minGainPerReference,
                                  leftSize, left.bounds, rightSize, right.bounds)) {
                // Each side in chunk order to its room in the parent's spare room; the chunks'
                // parts are copied on the team.
                placeChildren(task, leftSize, rightSize, task.spare, task.first, left, right);
                std::vector<std::size_t> leftAt(chunks), rightAt(chunks);
                std::size_t l = 0, r = 0;
                for (std::size_t i = 0; i < chunks; ++i) {
                    leftAt[i] = l;
                    rightAt[i] = r;
                    l += lefts[i].size();
                    r += rights[i].size();
                }
                team.forEach(chunks, [&](std::size_t i) {
                    std::copy(lefts[i].begin(), lefts[i].end(), left.first + leftAt[i]);
                    std::copy(rights[i].begin(), rights[i].end(), right.first + rightAt[i]);
                });
            } else {
                kind = choice.fallback;
                left.bounds = right.bounds = RecordBounds{};
            }
        }
        if (kind == SplitKind::Object) {
            // Each chunk's references go to their places in the spare room (offsets from the
            // chunks' bins), in the order of the parent; the parent's room becomes the spare.
            placeChildren(task, choice.object.leftCount, count - choice.object.leftCount,
                          task.spare, task.first, left, right);
            std::vector<std::size_t> leftAt(chunks), rightAt(chunks);
            std::size_t l = 0, r = 0;
            for (std::size_t i = 0; i < chunks; ++i) {
                leftAt[i] = l;
                rightAt[i] = r;
                const uint32_t n = chunks == 1 ? choice.object.leftCount
                                               : leftCountOf(chunkBins[i], choice.object);
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
        } else if (kind == SplitKind::Leaf) {
            out.addLeaf(task.slot, task.first, count);
            continue;
        }
        splitIntoChildren(task, left, right, out, stack);
    }
}

} // namespace raylab
