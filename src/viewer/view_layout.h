#pragma once
// Where the window shows what: the panel's column at the left edge and the traced picture in
// the rest, decided once a frame by viewLayout from the framebuffer's size, whether the panel is
// shown and its width. Everything that draws the picture or maps the mouse to its pixels (the
// quad, the overlays, the divider, the readouts, Ctrl+click, the orbit's pivot) takes the
// picture's box from here: the panel never covers the picture, and the render resolution is the
// picture's box times the resolution scale.
//
// Boxes are in framebuffer pixels, x to the right and y down from the framebuffer's top, as the
// cursor (cursorInPixels) and Dear ImGui count; glBox turns one into GL's bottom-up rectangle.

#include "io/command_line.h"

namespace raylab::viewer {

// The panel's column at UI scale 1, in Dear ImGui units (screen coordinates): its width at
// first, and the least it can be dragged to (view_layout.cpp scales both).
inline constexpr float kPanelColumnWidth = 360.0f;
inline constexpr float kMinPanelColumnWidth = 200.0f;

// Dear ImGui units at `uiScale` in framebuffer pixels (framebufferScale pixels a unit), rounded.
int scaledPixels(float units, float uiScale, float framebufferScale);

struct PixelBox {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
    // Whether the framebuffer point (x, y) lies inside: x <= px < x + width, likewise for y.
    bool contains(double px, double py) const;
    bool operator==(const PixelBox&) const = default;
};

struct ViewLayout {
    int framebufferWidth = 0;
    int framebufferHeight = 0;
    PixelBox panel;   // the panel's column, the framebuffer's height; empty: no panel drawn
    PixelBox picture; // the traced picture's area: the rest, at least 1 x 1 unless the
                      // framebuffer is empty
    bool panelShown() const { return !panel.empty(); }
};

// The panel (when `panelShown`) takes `panelWidth` pixels at the left edge, less when the
// framebuffer is too narrow to leave the picture a pixel; a panel that would then be narrower
// than `minPanelWidth` is not drawn and the picture takes the whole framebuffer. The picture is
// the rest. An empty framebuffer (minimised) gives empty boxes.
ViewLayout viewLayout(int framebufferWidth, int framebufferHeight, bool panelShown, int panelWidth,
                      int minPanelWidth);

// The pixel (px, py) of a renderWidth x renderHeight picture shown stretched over `picture`
// (as shaders/quad.frag shows it) under framebuffer point (x, y); false outside the box (or for
// an empty box or picture).
bool pixelUnderCursor(double x, double y, const PixelBox& picture, int renderWidth,
                      int renderHeight, int& px, int& py);

// The framebuffer pixels that show the renderWidth x renderHeight picture's pixels px0..px1 by
// py0..py1 (inclusive, in either order) over `picture`: the inverse of pixelUnderCursor.
PixelBox pictureToFramebuffer(const PixelBox& picture, int renderWidth, int renderHeight, int px0,
                              int py0, int px1, int py1);

// A box in GL's window coordinates (x, y of its lower-left corner, rows from the bottom) of a
// framebuffer `framebufferHeight` pixels high, for glViewport and glScissor.
struct GlBox {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    bool operator==(const GlBox&) const = default;
};
GlBox glBox(const PixelBox& box, int framebufferHeight);

// `box` clipped to `within` (empty when they do not overlap).
PixelBox intersect(const PixelBox& box, const PixelBox& within);

// The Dear ImGui scale of the panel for a window whose content scale (glfwGetWindowContentScale)
// is contentScale and whose framebuffer has framebufferScale pixels per screen coordinate
// (2 on a macOS Retina screen, where Dear ImGui's coordinates are already points): their ratio,
// clamped to [kMinUiScale, kMaxUiScale] (io/command_line.h, as --ui-scale); 1 for a non-finite or
// non-positive input.
float uiScaleFor(float contentScale, float framebufferScale);

} // namespace raylab::viewer
