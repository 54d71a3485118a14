#include "orbit_controls.h"

#include "core/bvh/bvh.h"
#include "core/camera.h"

#include <algorithm>
#include <glm/geometric.hpp>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

static_assert(GLFW_MOUSE_BUTTON_RIGHT == 1 && GLFW_MOUSE_BUTTON_MIDDLE == 2);

// The point under the cursor: where the ray through that pixel's centre hits the scene, or the
// centre of the scene's bounds when it hits nothing.
namespace {

glm::vec3 pointUnderCursor(GLFWwindow* window, const LoadedScene& scene,
                           const RenderSettings& settings, const PixelBox& area) {
    double x = 0.0, y = 0.0;
    cursorInPixels(window, x, y);
    int px = 0, py = 0;
    if (pixelUnderCursor(x, y, area, settings.width, settings.height, px, py)) {
        const Ray ray = PrimaryRays(settings.camera, settings.width, settings.height)
                            .through(static_cast<float>(px) + 0.5f, static_cast<float>(py) + 0.5f);
        if (const Hit hit = closestHit(scene.bvh, ray); hit.found()) {
            return ray.origin + hit.t * ray.direction;
        }
    }
    const Aabb bounds = scene.scene.bounds();
    return bounds.empty() ? glm::vec3(0.0f) : bounds.center();
}

} // namespace

// The orbit (right drag, or Alt + left: about the point under the cursor at the press) and the
// pan (middle drag: the point under the cursor follows it) applied to `settings`.
void applyOrbitAndPan(const InputEvents& events, bool panelHasMouse, GLFWwindow* window,
                      const LoadedScene& scene, const PixelBox& area, OrbitControls& controls,
                      RenderSettings& settings) {
    constexpr double kOrbitDegreesPerPixel = 0.3;
    const bool orbitStart = events.orbitPressed && !panelHasMouse;
    const bool panStart = events.panPressed && !panelHasMouse;
    if (orbitStart || panStart) {
        controls.pivot = pointUnderCursor(window, scene, settings, area);
    }
    double dx = 0.0, dy = 0.0;
    if (controls.orbit.update(window, orbitStart, dx, dy) && (dx != 0.0 || dy != 0.0)) {
        orbitCamera(settings.camera, controls.pivot,
                    static_cast<float>(-dx * kOrbitDegreesPerPixel),
                    static_cast<float>(dy * kOrbitDegreesPerPixel));
    }
    if (controls.pan.update(window, panStart, dx, dy) && (dx != 0.0 || dy != 0.0)) {
        // World units per framebuffer pixel at the pivot's distance.
        const float perPixel =
            glm::length(controls.pivot - settings.camera.position) /
            focalLengthPixels(settings.camera.verticalFovDegrees, std::max(area.height, 1));
        panCamera(settings.camera, static_cast<float>(dx) * perPixel,
                  static_cast<float>(dy) * perPixel);
    }
}

} // namespace raylab::viewer
