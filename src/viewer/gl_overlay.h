#pragma once
// What the viewer draws over the traced picture with GL (never into the picture or its
// screenshots): the split's divider, the inspected pixel's marker, a rectangle's outline and the
// inspected pixel's rays. Call them after the picture's quad; each draws inside the picture's box
// of the layout (view_layout.h) only, never over the panel.

#include "ray_overlay_geometry.h"
#include "view_layout.h"

#include <span>
#include <string>

namespace raylab::viewer {

// The split's divider: a white line two pixels wide at `column` of the picture's box.
void drawDivider(const ViewLayout& layout, int column);
// A square outline around pixel (px, py) of a width x height picture shown over the box.
void drawPixelMarker(const ViewLayout& layout, int px, int py, int width, int height);
// The outline (white, 1 framebuffer pixel wide) of picture pixels x0..x1 by y0..y1 (inclusive,
// in either order) of a width x height picture.
void drawPixelRectangle(const ViewLayout& layout, int x0, int y0, int x1, int y1, int width,
                        int height);

// The inspected pixel's rays (ray_overlay_geometry.h) as lines kRayLineWidth framebuffer pixels
// wide in overlayColour(kind). Needs a current OpenGL 3.3 core context for its whole life.
class OverlayLines {
public:
    static constexpr float kRayLineWidth = 2.0f;

    OverlayLines() = default;
    OverlayLines(const OverlayLines&) = delete;
    OverlayLines& operator=(const OverlayLines&) = delete;
    ~OverlayLines();

    // Compiles the shaders and makes the vertex buffer. False with a one-line error.
    bool create(std::string& error);

    // Draws segments in pixels of a width x height picture shown over the layout's picture box,
    // clipped to it.
    void draw(std::span<const ImageSegment> segments, int width, int height,
              const ViewLayout& layout);

private:
    unsigned program_ = 0;
    unsigned vertexArray_ = 0;
    unsigned buffer_ = 0;
    int viewportSizeLocation_ = -1;
};

} // namespace raylab::viewer
