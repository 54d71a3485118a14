#include "gl_overlay.h"

#include "gl_program.h"
#include "overlay_shaders.h"

#include <algorithm>
#include <glad/gl.h>
#include <vector>

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

void drawPixelRectangle(int x0, int y0, int x1, int y1, int width, int height, int framebufferWidth,
                        int framebufferHeight) {
    if (width <= 0 || height <= 0) {
        return;
    }
    // The framebuffer pixels that show the rectangle's pixels; GL's rows count from the bottom.
    const int left = std::min(x0, x1) * framebufferWidth / width;
    const int right = (std::max(x0, x1) + 1) * framebufferWidth / width;
    const int top = std::min(y0, y1) * framebufferHeight / height;
    const int bottom = (std::max(y0, y1) + 1) * framebufferHeight / height;
    const int low = framebufferHeight - bottom;
    const int w = std::max(right - left, 1);
    const int h = std::max(bottom - top, 1);
    const int rects[4][4] = {
        {left, low, w, 1}, {left, low + h - 1, w, 1}, {left, low, 1, h}, {left + w - 1, low, 1, h}};
    glEnable(GL_SCISSOR_TEST);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    for (const auto& r : rects) {
        glScissor(std::max(r[0], 0), std::max(r[1], 0), r[2], r[3]);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
}

OverlayLines::~OverlayLines() {
    if (buffer_ != 0) {
        glDeleteBuffers(1, &buffer_);
    }
    deleteGlObjects(program_, vertexArray_, 0, 0);
}

bool OverlayLines::create(std::string& error) {
    program_ =
        buildProgram(kOverlayVertexShader, kOverlayFragmentShader, "the overlay's lines", error);
    if (program_ == 0) {
        return false;
    }
    viewportSizeLocation_ = glGetUniformLocation(program_, "uViewportSize");
    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &buffer_);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    // Per vertex: x, y (framebuffer pixels), then r, g, b.
    constexpr GLsizei kStride = 5 * sizeof(float);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, kStride, nullptr);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, kStride,
                          reinterpret_cast<const void*>(2 * sizeof(float)));
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void OverlayLines::draw(std::span<const ImageSegment> segments, int width, int height,
                        int framebufferWidth, int framebufferHeight) {
    if (program_ == 0 || segments.empty() || width <= 0 || height <= 0 || framebufferWidth <= 0 ||
        framebufferHeight <= 0) {
        return;
    }
    // Picture pixels (y down) to framebuffer pixels (y up), then a quad per segment.
    const float sx = static_cast<float>(framebufferWidth) / static_cast<float>(width);
    const float sy = static_cast<float>(framebufferHeight) / static_cast<float>(height);
    const auto toFramebuffer = [&](const glm::vec2& p) {
        return glm::vec2(p.x * sx, static_cast<float>(framebufferHeight) - p.y * sy);
    };
    std::vector<float> vertices;
    std::vector<glm::vec2> corners;
    for (const ImageSegment& segment : segments) {
        corners.clear();
        appendLineQuad(toFramebuffer(segment.from), toFramebuffer(segment.to), kRayLineWidth,
                       corners);
        const glm::vec3 colour = overlayColour(segment.kind);
        for (const glm::vec2& c : corners) {
            vertices.insert(vertices.end(), {c.x, c.y, colour.x, colour.y, colour.z});
        }
    }
    if (vertices.empty()) {
        return;
    }
    glViewport(0, 0, framebufferWidth, framebufferHeight);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_);
    glUniform2f(viewportSizeLocation_, static_cast<float>(framebufferWidth),
                static_cast<float>(framebufferHeight));
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)),
                 vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size() / 5));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace raylab::viewer
