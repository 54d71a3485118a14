#include "gl_overlay.h"

#include "gl_program.h"
#include "overlay_shaders.h"

#include <algorithm>
#include <array>
#include <glad/gl.h>
#include <vector>

namespace raylab::viewer {

namespace {

// Fills the framebuffer boxes `boxes`, clipped to the layout's picture, with one colour.
void fillBoxes(const ViewLayout& layout, std::span<const PixelBox> boxes, float r, float g,
               float b) {
    glEnable(GL_SCISSOR_TEST);
    glClearColor(r, g, b, 1.0f);
    for (const PixelBox& box : boxes) {
        const PixelBox clipped = intersect(box, layout.picture);
        if (!clipped.empty()) {
            const GlBox gl = glBox(clipped, layout.framebufferHeight);
            glScissor(gl.x, gl.y, gl.width, gl.height);
            glClear(GL_COLOR_BUFFER_BIT);
        }
    }
    glDisable(GL_SCISSOR_TEST);
}

// The four sides, `thickness` pixels wide, of the framebuffer box `box`, inside it.
std::array<PixelBox, 4> outline(const PixelBox& box, int thickness) {
    return {PixelBox{box.x, box.y, box.width, thickness},
            PixelBox{box.x, box.y + box.height - thickness, box.width, thickness},
            PixelBox{box.x, box.y, thickness, box.height},
            PixelBox{box.x + box.width - thickness, box.y, thickness, box.height}};
}

} // namespace

// Drawn by GL over the quad, never into the traced picture or its screenshots.
void drawDivider(const ViewLayout& layout, int column) {
    const PixelBox line{layout.picture.x + column - 1, layout.picture.y, 2, layout.picture.height};
    fillBoxes(layout, std::span(&line, 1), 1.0f, 1.0f, 1.0f);
}

void drawPixelMarker(const ViewLayout& layout, int px, int py, int width, int height) {
    const PixelBox pixel = pictureToFramebuffer(layout.picture, width, height, px, py, px, py);
    if (pixel.empty()) {
        return;
    }
    // A square 8 pixels wider than the pixel's, about its centre.
    const int size = std::max(pixel.width, pixel.height) + 8;
    const PixelBox square{pixel.x + pixel.width / 2 - size / 2,
                          pixel.y + pixel.height - pixel.height / 2 - size / 2, size, size};
    fillBoxes(layout, outline(square, 2), 1.0f, 0.2f, 0.8f);
}

void drawPixelRectangle(const ViewLayout& layout, int x0, int y0, int x1, int y1, int width,
                        int height) {
    const PixelBox box = pictureToFramebuffer(layout.picture, width, height, x0, y0, x1, y1);
    if (!box.empty()) {
        fillBoxes(layout, outline(box, 1), 1.0f, 1.0f, 1.0f);
    }
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
                        const ViewLayout& layout) {
    const PixelBox& area = layout.picture;
    if (program_ == 0 || segments.empty() || width <= 0 || height <= 0 || area.empty()) {
        return;
    }
    // Picture pixels (y down) to pixels of the picture's box (y up from its bottom edge: the
    // viewport below is the box), then a quad per segment.
    const float sx = static_cast<float>(area.width) / static_cast<float>(width);
    const float sy = static_cast<float>(area.height) / static_cast<float>(height);
    const auto toFramebuffer = [&](const glm::vec2& p) {
        return glm::vec2(p.x * sx, static_cast<float>(area.height) - p.y * sy);
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
    // The viewport clips the lines to the picture's box.
    const GlBox viewport = glBox(area, layout.framebufferHeight);
    glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_);
    glUniform2f(viewportSizeLocation_, static_cast<float>(area.width),
                static_cast<float>(area.height));
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
