#pragma once
// What Dear ImGui's draw data of one frame would draw, summed up: a 64-bit hash of everything
// the OpenGL3 renderer reads (display position, size and framebuffer scale; every draw list's
// vertices and indices; every command's clip rectangle, texture, offsets, count and callback)
// and the framebuffer rectangle that the commands can touch. Two frames with equal signatures
// draw the same pixels (up to a hash collision, about 2^-64), so the panel's pixels of the first
// can be reused for the second (panel_cache.h). Reads the draw data only: no GL.

#include <cstdint>

struct ImDrawData;

namespace raylab::viewer {

// A rectangle of framebuffer pixels, rows counted from the top (ImGui's convention): columns
// [x0, x1), rows [y0, y1). Empty when x1 <= x0 or y1 <= y0.
struct PixelRect {
    int x0 = 0;
    int y0 = 0;
    int x1 = 0;
    int y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool operator==(const PixelRect&) const = default;
};

// The smallest rectangle holding both (an empty one adds nothing).
PixelRect unite(const PixelRect& a, const PixelRect& b);

struct PanelSignature {
    std::uint64_t hash = 0;
    // The union over the commands of their triangles' bounding box within their clip rectangle,
    // in framebuffer pixels (scaled by the framebuffer scale), rounded outwards and clamped to
    // the framebuffer: the renderer writes no pixel outside it. Empty when nothing is drawn.
    PixelRect bounds;
    bool operator==(const PanelSignature&) const = default;
};

// The signature of a frame's draw data (ImGui::GetDrawData() after ImGui::Render()). Costs a
// pass over the vertex and index buffers (a few hundred kilobytes for the panel: tens of us).
PanelSignature panelSignature(const ImDrawData& data);

} // namespace raylab::viewer
