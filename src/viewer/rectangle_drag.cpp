#include "rectangle_drag.h"

#include "input.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

bool RectangleDrag::update(GLFWwindow* window, bool start, const PixelBox& area, int width,
                           int height, std::optional<PixelRectangle>& rectangle) {
    if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS && !start) {
        dragging_ = false;
        return false;
    }
    if (!start && !dragging_) {
        return false;
    }
    double x = 0.0, y = 0.0;
    cursorInPixels(window, x, y);
    // A drag that goes on past the picture's edge (over the panel, out of the window) ends at
    // the edge's pixels; a press must be on the picture.
    if (!start) {
        x = std::clamp(x, static_cast<double>(area.x),
                       std::max(static_cast<double>(area.x + area.width) - 1.0, 0.0));
        y = std::clamp(y, static_cast<double>(area.y),
                       std::max(static_cast<double>(area.y + area.height) - 1.0, 0.0));
    }
    int px = 0, py = 0;
    if (!pixelUnderCursor(x, y, area, width, height, px, py)) {
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
