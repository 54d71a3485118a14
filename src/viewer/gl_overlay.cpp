#include "gl_overlay.h"

#include <algorithm>
#include <glad/gl.h>

namespace raylab::viewer {

// The split's divider: a white line two pixels wide over the picture at framebuffer column x
// (drawn by GL over the quad, never into the traced picture or its screenshots).
void drawDivider(int x, int framebufferHeight) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(std::max(x - 1, 0), 0, 2, framebufferHeight);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

// A square outline around the inspected pixel (px, py) of a width x height picture shown over
// the whole framebuffer, drawn by GL over the quad.
void drawPixelMarker(int px, int py, int width, int height, int framebufferWidth,
                     int framebufferHeight) {
    const int x0 = px * framebufferWidth / width;
    const int x1 = (px + 1) * framebufferWidth / width;
    const int top = py * framebufferHeight / height;
    const int bottom = (py + 1) * framebufferHeight / height;
    // GL's rows count from the bottom.
    const int y0 = framebufferHeight - bottom;
    const int size = std::max(x1 - x0, bottom - top) + 8;
    const int cx = (x0 + x1) / 2;
    const int cy = y0 + (bottom - top) / 2;
    glEnable(GL_SCISSOR_TEST);
    glClearColor(1.0f, 0.2f, 0.8f, 1.0f);
    const int left = cx - size / 2;
    const int low = cy - size / 2;
    const int rects[4][4] = {{left, low, size, 2},
                             {left, low + size - 2, size, 2},
                             {left, low, 2, size},
                             {left + size - 2, low, 2, size}};
    for (const auto& r : rects) {
        glScissor(std::max(r[0], 0), std::max(r[1], 0), r[2], r[3]);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
}

} // namespace raylab::viewer
