#pragma once
// The orbit (right drag, or Alt + left drag: about the point under the cursor at the press) and
// the pan (middle drag) of the viewer's camera.

#include "core/render_settings.h"
#include "input.h"
#include "loaded_scene.h"

#include <glm/vec3.hpp>

struct GLFWwindow;

namespace raylab::viewer {

// The orbit's and the pan's drags and the point they turn about or keep in view.
struct OrbitControls {
    ButtonDrag orbit{1}; // GLFW_MOUSE_BUTTON_RIGHT
    ButtonDrag pan{2};   // GLFW_MOUSE_BUTTON_MIDDLE
    glm::vec3 pivot{0.0f};
};

// The orbit and the pan of this frame's events applied to settings.camera; `panelHasMouse`:
// Dear ImGui wants the mouse (no drag starts); the picture is shown over the framebuffer's box
// `area` (view_layout.h).
void applyOrbitAndPan(const InputEvents& events, bool panelHasMouse, GLFWwindow* window,
                      const LoadedScene& scene, const PixelBox& area, OrbitControls& controls,
                      RenderSettings& settings);

} // namespace raylab::viewer
