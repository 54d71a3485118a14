#pragma once
// The inspected pixel's rays as the viewer draws them over the picture (GL-free; gl_overlay.h
// draws the result): world-space segments (the camera ray to the hit, the shadow ray to the light
// or to its blocker, the path integrator's surfaces as a polyline), clipped at a near plane and
// projected with the current camera by the tracer's own projection (PrimaryRays::cameraFrom and
// imageFrom, core/camera.h), then clipped to the picture.

#include "core/camera.h"
#include "core/integrators/pixel_inspection.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace raylab::viewer {

// The near plane's depth for a scene whose navigation step is `step` (core's navigationStep):
// 1% of a step, 1e-3 world units in the lab's box.
inline constexpr float kNearDepthPerStep = 0.01f;

enum class OverlayRay {
    Camera,        // from the camera the pixel was picked with to the hit
    ShadowClear,   // from the hit to the light's centre, nothing in between
    ShadowBlocked, // from the hit to the closest blocker
    Path,          // from one surface of the inspected path to the next
    LabCamera,     // the observer view's lab camera: marker, frustum, image plane
    Light,         // the observer view's light: marker, circle of its radius
};

struct WorldSegment {
    glm::vec3 from{0.0f}, to{0.0f}; // world units
    OverlayRay kind = OverlayRay::Camera;
};

struct ImageSegment {
    glm::vec2 from{0.0f}, to{0.0f}; // picture pixels, x right, y down from the top edge
    OverlayRay kind = OverlayRay::Camera;
};

// The segments of an inspection whose camera ray started at `rayOrigin`: none for a miss; the
// camera ray; the shadow ray when it was traced (to the blocker at its t along the unit ray
// towards the light when blocked); one Path segment between consecutive path vertices.
std::vector<WorldSegment> inspectionSegments(const PixelInspection& inspection,
                                             const glm::vec3& rayOrigin);

// A segment as the camera `rays` (of a width x height picture) sees it: the part at depth >=
// nearDepth (world units, > 0), projected, then the part inside [0, width] x [0, height]. False
// when nothing of it is left.
bool projectSegment(const PrimaryRays& rays, int width, int height, float nearDepth,
                    const WorldSegment& segment, ImageSegment& out);

// Every segment that projectSegment keeps, in order.
std::vector<ImageSegment> projectSegments(const PrimaryRays& rays, int width, int height,
                                          float nearDepth,
                                          const std::vector<WorldSegment>& segments);

// The colour a kind of ray is drawn in, components 0 or 1 (saturated colours that the lab's
// picture, lit with an indirect term, never shows): camera ray green, clear shadow ray yellow,
// blocked shadow ray red, path magenta, the observer view's lab camera white and light cyan.
glm::vec3 overlayColour(OverlayRay kind);

// The two triangles (6 vertices of x, y) that draw segment a-b, in framebuffer pixels, as a line
// `width` pixels wide; none for a segment shorter than 1e-3 pixels.
void appendLineQuad(const glm::vec2& a, const glm::vec2& b, float width,
                    std::vector<glm::vec2>& vertices);

} // namespace raylab::viewer
