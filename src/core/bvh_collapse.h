#pragma once
// Collapses the binary BVH into the 8-wide form of bvh_wide.h (internal to core).

#include "bvh.h"

namespace raylab {

// Largest traversal stack the wide BVH may need; buildWideBvh leaves the wide form empty (the
// scalar path then runs) for a tree that would need more.
inline constexpr int kWideStackSize = 512;

// Fills bvh.wideNodes and bvh.triangleBlocks from bvh.nodes and bvh.triangles; then the binary
// leaves index the blocks' lanes and bvh.triangles is emptied (see Bvh::triangles). Leaves bvh
// as it was when the tree does not fit the wide form.
void buildWideBvh(Bvh& bvh);

} // namespace raylab
