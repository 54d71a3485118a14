#pragma once
// Collapses the binary BVH into the 8-wide form of bvh_wide.h (internal to core).

#include "bvh/build/bvh_build_team.h"
#include "bvh/bvh.h"

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

// Fills bvh.wideNodes and bvh.triangleBlocks from bvh.nodes, whose leaves hold leaf triangles
// [index, index + count), leaf triangle i being scene.triangles[leafScene[i]]; then, with
// `pointBinaryLeaves` (for a BVH that keeps its binary nodes), points the binary leaves at the
// blocks' lanes (see Bvh::triangles), and returns true. Returns false, with the wide form empty
// and bvh.nodes unchanged, when the tree does not fit the wide form. The top of the wide tree is
// made on the calling thread, its subtrees on the team; the result does not depend on the
// team's size.
bool buildWideBvh(Bvh& bvh, const Scene& scene, const std::vector<uint32_t>& leafScene,
                  bool pointBinaryLeaves, BuildTeam& team);

} // namespace raylab
