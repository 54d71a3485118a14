#pragma once
// Pre-splitting of triangles whose bounding box is much larger than the triangle (internal to
// core): long thin diagonal triangles, common in architectural scenes such as Sponza. Before the
// build, such a triangle is split into several references, each with the box of the part of the
// triangle inside a smaller box, so the SAH build can place the parts in tight leaves (the idea
// of "early split clipping"; the allocation of splits follows Karras and Aila's pre-splitting).
//
// A triangle may then sit in several leaves; every part of it is covered by some reference's
// box, so traversal still finds every hit, and a repeated triangle gives the same t, u, v and
// index wherever it is tested, so answers do not change.

#include "bvh/build/bvh_binning.h"
#include "bvh/build/bvh_build_team.h"
#include "scene.h"

#include <vector>

namespace raylab {

// Replaces records (one per valid triangle) by references: at most about budget * records.size()
// extra ones, given to the triangles with the most box surface beyond their own area. `slack`
// (world units) widens each split box to cover the rounding of the edge-plane intersections.
// Deterministic: depends only on the triangles and the arguments, not on the team's size. Returns
// whether it replaced the records (false: they are left as they were).
bool presplitRecords(const Scene& scene, float budget, float slack, BuildTeam& team,
                     RecordVector& records);

} // namespace raylab
