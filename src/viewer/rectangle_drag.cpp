#include "rectangle_drag.h"

#include "input.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

bool RectangleDrag::update(GLFWwindow* window, bool start, int framebufferWidth,
                           int framebufferHeight, int width, int height,
                           std::optional<PixelRectangle>& rectangle) {
    if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS && !start) {
        dragging_ = false;
        return false;
    }
    if (!start && !dragging_) {
        return false;
    }
    double x = 0.0, y = 0.0;
    cursorInPixels(window, x, y);
    // The cursor held inside the framebuffer, so a drag past an edge ends at the edge's pixels.
    x = std::clamp(x, 0.0, std::max(static_cast<double>(framebufferWidth) - 1.0, 0.0));
    y = std::clamp(y, 0.0, std::max(static_cast<double>(framebufferHeight) - 1.0, 0.0));
    int px = 0, py = 0;
    if (!pixelUnderCursor(x, y, framebufferWidth, framebufferHeight, width, height, px, py)) {
        dragging_ = false;
        return false;
    }
    if (start) {
        dragging_ = true;
        rectangle = PixelRectangle{px, py, px, py};
    } else if (rectangle) {
        rectangle->x1 = px;
        rectangle->y1 = py;
    }
    return dragging_;
}

} // namespace raylab::viewer
