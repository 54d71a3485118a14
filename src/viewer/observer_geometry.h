#pragma once
// The observer view's geometry (GL-free; gl_overlay.h draws it): where the observer camera
// starts, and the world segments drawn over the observer's picture: the lab camera (its position,
// its frustum's edges to an image plane and that plane's outline) and the light (a marker, and a
// circle of its radius). They are projected like the inspected pixel's rays
// (ray_overlay_geometry.h), with the observer's camera, clipped at its near plane.

#include "core/aabb.h"
#include "core/camera.h"
#include "core/render_settings.h"
#include "ray_overlay_geometry.h"

#include <array>
#include <glm/vec3.hpp>
#include <vector>

namespace raylab::viewer {

// The scene's size for the observer (world units): the bounds' diagonal, 1 for empty or flat-out
// degenerate bounds.
float observedSceneSize(const Aabb& bounds);

// The observer's first camera: behind the lab camera (on the line from the scene's centre through
// it, one scene size further) and 0.4 scene sizes above it, looking at the scene's centre, with
// the lab's field of view (53.13 degrees), so that the lab camera, its frustum and the scene are
// in view.
Camera observerStart(const Camera& lab, const Aabb& bounds);

// The depth (world units along the lab camera's forward axis) of the image plane drawn: halfway
// to the scene's centre, and at least a quarter of the scene's size.
float imagePlaneDistance(const Camera& lab, const Aabb& bounds);

// The image plane's corners at `depth` (> 0, world units along forward) of a width x height
// picture seen by `lab`: the world points of depth `depth` on the rays through the picture's
// corners (0, 0), (width, 0), (width, height), (0, height) (pixel units, y down), in that order.
std::array<glm::vec3, 4> imagePlaneCorners(const PrimaryRays& lab, int width, int height,
                                           float depth);

// The lab camera's segments (OverlayRay::LabCamera): a marker at its position (three segments of
// half-length `marker` along the world axes), its frustum's four edges from its position to the
// image plane's corners at `depth`, and the plane's outline.
std::vector<WorldSegment> labCameraSegments(const Camera& lab, int width, int height, float depth,
                                            float marker);

// The light's segments (OverlayRay::Light): a marker at its centre (three segments of half-length
// `marker` along the world axes) and, when its radius is > 0, a circle of that radius
// (kLightCircleSegments segments) about its centre, in the plane facing `viewer`.
inline constexpr int kLightCircleSegments = 32;
std::vector<WorldSegment> lightSegments(const PointLight& light, const glm::vec3& viewer,
                                        float marker);

// What the observer view draws over the observer's width x height picture seen with `observer`:
// the segments of the lab camera `lab` (its picture being labWidth x labHeight) and of the light,
// projected and clipped at nearDepth (world units) by projectSegments. Marker sizes are 2% of the
// scene's size. (The inspected pixel's rays are drawn as in the lab camera's view, with the
// camera of the picture shown.)
std::vector<ImageSegment> observerOverlay(const Camera& observer, int width, int height,
                                          const Camera& lab, int labWidth, int labHeight,
                                          const PointLight& light, const Aabb& bounds,
                                          float nearDepth);

} // namespace raylab::viewer
