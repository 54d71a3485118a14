#pragma once
// Default camera, light and epsilon for a scene that came without them.

#include "render_settings.h"
#include "scene.h"

namespace raylab {

// The lab's shadow epsilon scaled to a scene: 1e-3 for the lab's box (diagonal 2*sqrt(3)),
// proportionally more or less for bigger or smaller scenes.
float scaledShadowEpsilon(const Aabb& bounds);

// The step one key press moves the camera or light: 0.1 for the lab's box, scaled likewise.
float navigationStep(const Aabb& bounds);

// Frames a scene: the camera looks level at the centre of the bounding box, along +z or, for a
// scene open on another side (a box with one wall missing), into the opening (framingSide,
// scene_view_side.h), from far enough to see all of it at the current field of view and aspect;
// the light sits above and in front; the shadow epsilon scales with the scene's size. Other
// settings are kept. An empty scene is left as is.
void frameScene(const Scene& scene, RenderSettings& settings);

} // namespace raylab
