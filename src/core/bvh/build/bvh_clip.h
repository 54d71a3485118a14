#pragma once
// Splitting a triangle reference at an axis-aligned plane (internal to core), shared by
// pre-splitting (bvh_presplit.cpp) and the build's spatial splits (bvh_spatial_split.cpp).

#include "aabb.h"
#include "scene.h"

namespace raylab {

// The boxes of the parts of triangle t inside `box` on either side of the plane
// x[axis] = position, each widened by slack (world units, to cover the rounding of the
// edge-plane intersections) and then clipped to `box`. A side the triangle does not reach is
// empty(). Every point of t inside `box` lies in left or in right.
void splitBox(const Triangle& t, const Aabb& box, int axis, float position, float slack, Aabb& left,
              Aabb& right);

} // namespace raylab
