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

// Which of the placed settings the user gave (by flag, settings file or panel): placeForScene
// keeps these.
struct GivenSettings {
    bool cameraPosition = false;
    bool cameraYaw = false;
    bool cameraPitch = false;
    bool cameraFov = false; // --fov or --focal
    bool lightPosition = false;
    bool lightColor = false;
    bool lightIntensity = false;
    bool shadowEpsilon = false;
};

// Where a new scene's camera and light go, the one rule of every program: the lab's camera, light
// and shadow epsilon for the lab's box, frameScene's for a mesh, except the fields `given` keeps
// as they are in `settings`. Every other setting is kept.
void placeForScene(const Scene& scene, bool isLabBox, const GivenSettings& given,
                   RenderSettings& settings);

} // namespace raylab
