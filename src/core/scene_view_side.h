#pragma once
// Which side a framed camera looks at a scene from (scene_framing.h). Looking along +z suits a
// closed mesh (a bunny, a dragon) from any side, but not a room or a box with one wall missing,
// such as the Cornell box's OBJ, whose +z view may be the back of a wall. The test here needs no
// BVH and no particular winding of the triangles: it measures how deep each side's view reaches.

#include "scene.h"

namespace raylab {

// A horizontal direction a camera can look along, as its yaw (camera.h: forwardOf).
enum class ViewSide { AlongPlusZ, AlongMinusZ, AlongPlusX, AlongMinusX };

float yawDegreesOf(ViewSide side);

// How deep a camera looking along each side sees into the scene, from 0 to 1, indexed by
// ViewSide: the scene's triangles are drawn into a kViewDepthGrid x kViewDepthGrid grid over the
// bounding box's face across the view (the nearest triangle of each cell, at the cell's centre);
// a side's depth is the mean over the cells of how far behind the box's near face that triangle
// lies, as a fraction of the box's depth (a cell no triangle covers counts 0). Triangles with a
// non-finite vertex are left out.
inline constexpr int kViewDepthGrid = 32;
struct ViewDepths {
    float value[4] = {0.0f, 0.0f, 0.0f, 0.0f};
};
ViewDepths viewDepths(const Scene& scene);

// The side a framed camera looks from: along +z, unless another side's view reaches more than
// half the box deep and more than twice as deep as +z's (an opening on that side).
ViewSide framingSide(const Scene& scene);

} // namespace raylab
