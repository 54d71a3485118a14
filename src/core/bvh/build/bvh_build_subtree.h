#pragma once
// The binned SAH builder of bvh_build.cpp (internal to core): builds the binary subtree of a set
// of references, splitting nodes by the best object split (bvh_build_object_split.h) or, where
// its children overlap much, the best spatial split (bvh_spatial_split.h), within a budget of
// extra references.

#include "bvh/build/bvh_binning.h"
#include "bvh/build/bvh_build_object_split.h"
#include "bvh/build/bvh_build_team.h"
#include "bvh/build/bvh_slot_array.h"
#include "bvh/build/bvh_spatial_split.h"
#include "bvh/bvh.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab {

// The references [first, first + count) of a subtree waiting to become the node at
// nodes[slot]. The task has the records [first, first + room()) and [spare, spare + room()) to
// itself, free to overwrite but for its references: room for every reference its splits may
// make, so that its children take their parts of both ranges and nothing is allocated.
struct BuildTask {
    uint32_t slot = 0;
    PrimRecord* first = nullptr;
    uint32_t count = 0;
    RecordBounds bounds; // of the references: the node's box and its centroids' box
    int depth = 0;
    uint32_t splitBudget = 0; // extra references its spatial splits may still make
    PrimRecord* spare = nullptr;
    std::size_t room() const { return std::size_t{count} + splitBudget; }
};

// Sets task's children's counts and budgets and places them: what is left of task's split
// budget after the split's own extra references (leftCount + rightCount - task.count) is shared
// by their sizes; their references go at `to` (left's room, then right's), their spare rooms at
// the same offsets of `from`. The children's rooms then fill the parent's exactly.
void placeChildren(const BuildTask& task, std::size_t leftCount, std::size_t rightCount,
                   PrimRecord* to, PrimRecord* from, BuildTask& left, BuildTask& right);

// Splits task's references at the median in place (medianOrder), the right half moved on to
// leave the left its room, and places the children with their bounds.
void splitAtMedian(const BuildTask& task, BuildTask& left, BuildTask& right);

// What the build needs besides the references.
struct BuildContext {
    const Scene* scene = nullptr;     // null: no spatial splits
    float slack = 0.0f;               // splitBox's (bvh_clip.h)
    float minOverlapArea = 0.0f;      // spatial splits only where object splits overlap more
    float minNodeOverlap = 0.0f;      // ... and more than this fraction of the node's own surface
    float minGainPerReference = 0.0f; // BvhBuildOptions::spatialSplitMinGain
    // Nodes of at most this many references become leaves straight away, unbinned, whatever
    // BvhBuildOptions::maxLeafSize says (0: none): the collapse makes every such binary subtree
    // one wide leaf anyway (kLeafMerge, bvh_collapse.h).
    uint32_t leafAtMost = 0;
};

// A built subtree: nodes[0] is its root; a leaf node holds the leaf references [index, index +
// count) of leafTriangles, each the scene index of its triangle (all the BVH keeps of a record).
// Both arrays may lie in slots of arrays shared with the other subtrees (bvh_slot_array.h).
struct Subtree {
    SlotArray<BvhNode> nodes;
    SlotArray<uint32_t> leafTriangles;
    // Makes nodes[slot] a leaf of the references [first, first + count).
    void addLeaf(uint32_t slot, const PrimRecord* first, uint32_t count);
};

// Makes task's node (out.nodes[task.slot]) an inner node over two new nodes for left and right
// (placed: placeChildren) and pushes them on stack, left on top (so its subtree is built, and
// stored, first).
void splitIntoChildren(const BuildTask& task, BuildTask left, BuildTask right, Subtree& out,
                       std::vector<BuildTask>& stack);

// What a node's references should do, as SubtreeBuilder::choose decides it.
enum class SplitKind { Leaf, Median, Spatial, Object };

struct SplitChoice {
    SplitKind kind = SplitKind::Leaf;
    SplitKind fallback = SplitKind::Leaf; // when a Spatial split turns out empty or over budget
    ObjectSplit object;
    SpatialSplit spatial;
};

// Whether a spatial split that made leftSize and rightSize references (with these bounds) of a
// node's `count` is kept, as choose() meant it: both sides hold references, the extra ones fit
// the node's budget, a split chosen from a sample (SpatialSplit::sampled) is cheaper by the SAH
// than the node's object split, and the split lowers that cost by at least minGainPerReference
// times the fraction of references it adds (BvhBuildOptions::spatialSplitMinGain). Otherwise
// the node takes choice.fallback.
bool keepsSpatialSplit(const SplitChoice& choice, uint32_t count, uint32_t splitBudget,
                       float minGainPerReference, std::size_t leftSize,
                       const RecordBounds& leftBounds, std::size_t rightSize,
                       const RecordBounds& rightBounds);

class SubtreeBuilder {
public:
    SubtreeBuilder(const BvhBuildOptions& options, const BuildContext& context);

    // Both build the subtree of `root` into out: root at out.nodes[root.slot], the two children
    // of a split appended as a pair, the left child's subtree before the right one's.

    // The top of the tree, on the team (bvh_build_top.cpp), depth first: nodes of more than
    // `deferBelow` references are split, the large ones one at a time with the team's threads
    // (splitOnTeam), the others in batches, several at a time, each on one thread (splitNode),
    // their children taking their slots in the batch's order. Nodes of at most `deferBelow`
    // references that must split are appended to `deferred` instead, their references left
    // where they are. Which way a node is split and the batches depend only on the counts, so
    // the result does not depend on the team's size.
    void buildTop(Subtree& out, BuildTask root, BuildTeam& team, std::size_t deferBelow,
                  std::vector<BuildTask>& deferred) const;

    // A whole subtree on this thread, its references moving between their room and the spare
    // room at each split. Leaves' references go to out.leafTriangles in depth-first order, left
    // child first.
    void buildSubtree(Subtree& out, const BuildTask& root) const;

private:
    // The split of references [first, first + count) of a node, binned by chunks on the team
    // when there is one (each chunk's bins then stay in chunkBins), else in one go, into
    // `scratch`, which must come empty (as constructed) and is left empty.
    SplitChoice choose(const PrimRecord* first, uint32_t count, const RecordBounds& bounds,
                       int depth, uint32_t splitBudget, BuildTeam* team, BinSet& scratch,
                       std::vector<BinSet>& chunkBins) const;

    // Splits the node of `task` on this thread, as choose() chose: returns the kind of split
    // made and fills left and right, placed in the node's two ranges (placeChildren); Leaf: the
    // node stays a leaf. `scratch` as choose() takes it. Allocates nothing.
    SplitKind splitNode(const BuildTask& task, BinSet& scratch, BuildTask& left,
                        BuildTask& right) const;
    // The same with the team: the node's references cut into chunks whose size depends only on
    // their count (BuildChunks), bins merged and children written in chunk order.
    SplitKind splitOnTeam(const BuildTask& task, BuildTeam& team, BinSet& scratch,
                          std::vector<BinSet>& chunkBins, BuildTask& left, BuildTask& right) const;

    int maxLeaf_;
    int bins_;
    BuildContext context_;
};

// References per chunk of a node split on the team, at most.
inline constexpr std::size_t kBuildChunkSize = 16384;
// Chunks of a node split on the team, at least: a node of fewer than 2 kBuildChunkSize
// references still keeps every thread of a small team busy.
inline constexpr std::size_t kMinBuildChunks = 4;

// How a node's references [first, first + count) split on the team are cut into chunks: as
// evenly as they go, by a rule of the count alone (never of the team's size).
struct BuildChunks {
    std::size_t count = 0; // chunks
    explicit BuildChunks(std::size_t references)
        : count(std::max(kMinBuildChunks, (references + kBuildChunkSize - 1) / kBuildChunkSize)),
          references_(references) {}
    std::size_t begin(std::size_t i) const { return references_ * i / count; }
    std::size_t end(std::size_t i) const { return references_ * (i + 1) / count; }

private:
    std::size_t references_;
};

} // namespace raylab
