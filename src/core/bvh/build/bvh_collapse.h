#pragma once
// Collapses the binary BVH into the 8-wide form of bvh_wide.h (internal to core).

#include "bvh/build/bvh_build_team.h"
#include "bvh/bvh.h"
#include "bvh/bvh_wide.h"
#include "uninitialised_allocator.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab {

// Largest traversal stack the wide BVH may need; buildWideBvh leaves the wide form empty (the
// scalar path then runs) for a tree that would need more.
inline constexpr int kWideStackSize = 512;

// A binary subtree of at most this many triangles becomes one wide leaf (one block of 8 lanes).
// The binary builder makes such nodes leaves straight away when only the wide form is kept
// (bvh_build_subtree.h): splitting them would only reorder the lanes of that leaf.
inline constexpr uint32_t kLeafMerge = 8;

// The leaf triangles under a binary node: [first, first + count) in leaf order (a node's leaves
// hold consecutive leaf triangles, depth first); and whether the collapse opens the node into
// its children (if not, the node becomes one wide leaf).
struct LeafSpan {
    uint32_t first = 0, count = 0;
    bool opens = false;
};

// A wide leaf: child `slot` of its part's node `node`, whose triangles go to lanes
// [lane, lane + triangles.count) counted from the start of the part's block `block` (running on
// into the next block past lane 7).
struct LeafPlacement {
    LeafSpan triangles;
    uint32_t node = 0; // in the part's nodes
    uint32_t slot = 0;
    uint32_t block = 0; // in the part's blocks
    uint32_t lane = 0;
};

// The collapse's working arrays, which a build keeps for the next (BvhBuildMemory): the wide
// subtrees' nodes and leaves, each subtree in slots of these two (bvh_slot_array.h). Arrays of
// each subtree's own, on the heap, took 3,600 of the dragon's 3,800 page faults of a first build.
struct CollapseMemory {
    UninitialisedVector<BvhWideNode> nodes;
    UninitialisedVector<LeafPlacement> leaves;
};

// Fills spans[i] for the binary nodes i in [first, last), which the caller may run for disjoint
// ranges on several threads. Children always follow their parent; a child of a node in the range
// either lies in it or has its span filled already.
void spanBinaryNodes(const BvhNode* nodes, std::size_t first, std::size_t last, LeafSpan* spans);

// Fills bvh.wideNodes and bvh.triangleBlocks from bvh.nodes, whose leaves hold leaf triangles
// [index, index + count), leaf triangle i being scene.triangles[leafScene[i]], and whose spans
// (spanBinaryNodes) are `spans`; then, with `pointBinaryLeaves` (for a BVH that keeps its binary
// nodes), points the binary leaves at the blocks' lanes (see Bvh::triangles), and returns true.
// Returns false, with the wide form empty and bvh.nodes unchanged, when the tree does not fit
// the wide form. The top of the wide tree is made on the calling thread, its subtrees on the
// team, in `memory`; the result does not depend on the team's size.
bool buildWideBvh(Bvh& bvh, const Scene& scene, const UninitialisedVector<uint32_t>& leafScene,
                  const UninitialisedVector<LeafSpan>& spans, bool pointBinaryLeaves,
                  BuildTeam& team, CollapseMemory& memory);

} // namespace raylab
