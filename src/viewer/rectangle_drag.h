#pragma once
// Shift + left drag over the picture: a rectangle of pixels whose mean the panel shows
// (pixel_readout.h). The press fixes one corner, the cursor moves the other until the button is
// released; the rectangle then stays until the next one.

#include "pixel_readout.h"
#include "view_layout.h"

#include <optional>

struct GLFWwindow;

namespace raylab::viewer {

class RectangleDrag {
public:
    // `start`: a Shift + left press outside the panel happened now. The picture is width x height
    // pixels shown over the framebuffer's box `area` (view_layout.h). Updates `rectangle`
    // (picture pixels) while dragging; returns whether a drag is under way (then the press is
    // not the camera's).
    bool update(GLFWwindow* window, bool start, const PixelBox& area, int width, int height,
                std::optional<PixelRectangle>& rectangle);

private:
    bool dragging_ = false;
};

} // namespace raylab::viewer
