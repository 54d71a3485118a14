#pragma once
// The panel's readouts of the picture shown, kept up to date every frame: the pixel under the
// cursor (when the cursor is over the picture and not over the panel) and the rectangle dragged
// with Shift + left, with its mean (pixel_readout.h).

#include "input.h"
#include "pixel_readout.h"
#include "rectangle_drag.h"

#include <optional>

struct GLFWwindow;

namespace raylab::viewer {

class PictureReadouts {
public:
    // This frame's `events`; `panelHasMouse`: ImGui wants the mouse. `shown` is shown over the
    // framebuffer's box `area` (view_layout.h).
    void update(GLFWwindow* window, const InputEvents& events, bool panelHasMouse,
                const PixelBox& area, const ShownImage& shown);

    // The last pixel read under the cursor (kept when the cursor leaves the picture).
    const std::optional<PixelReadout>& hover() const { return hover_; }
    // The rectangle dragged, in pixels of the picture shown, and its mean.
    const std::optional<PixelRectangle>& rectangle() const { return rectangle_; }
    const std::optional<RectangleMean>& rectangleMean() const { return mean_; }

private:
    RectangleDrag drag_;
    std::optional<PixelReadout> hover_;
    std::optional<PixelRectangle> rectangle_;
    std::optional<RectangleMean> mean_;
};

} // namespace raylab::viewer
