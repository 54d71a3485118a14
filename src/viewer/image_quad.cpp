#include "image_quad.h"

#include "gl_program.h"
#include "quad_shaders.h"

#include <algorithm>
#include <chrono>
#include <glad/gl.h>
#include <utility>

namespace raylab::viewer {

ImageQuad::~ImageQuad() { deleteGlObjects(program_, vertexArray_, texture_, framebuffer_); }

bool ImageQuad::create(std::string& error) {
    program_ = buildProgram(kQuadVertexShader, kQuadFragmentShader, "the picture's quad", error);
    if (program_ == 0) {
        return false;
    }
    viewportOriginLocation_ = glGetUniformLocation(program_, "uViewportOrigin");
    viewportSizeLocation_ = glGetUniformLocation(program_, "uViewportSize");
    imageLocation_ = glGetUniformLocation(program_, "uImage");

    glGenVertexArrays(1, &vertexArray_); // core profile: drawing needs a bound vertex array
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &framebuffer_);
    return true;
}

void ImageQuad::upload(const Rgba8Image& image) { // B, G, R, A bytes
    if (image.width <= 0 || image.height <= 0) {
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    if (image.width != width_ || image.height != height_) {
        // Unsized GL_RGBA with BGRA data: drivers then keep the texture in BGRA, the window's
        // own order, so the upload and the blit below are copies. Mesa's llvmpipe: 0.4 against
        // 4.1 ms of CPU per 1280 x 720 frame for a GL_RGBA8 texture of RGBA data (PERFORMANCE.md).
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, image.width, image.height, 0, GL_BGRA,
                     GL_UNSIGNED_BYTE, nullptr);
        width_ = image.width;
        height_ = image.height;
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_,
                               0);
        blitReady_ = glCheckFramebufferStatus(GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    }
    // Image row 0 goes to texture row 0; the fragment shader shows texture row 0 at the top.
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_BGRA, GL_UNSIGNED_BYTE,
                    image.pixels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    uploadSeconds_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void ImageQuad::draw(const ViewLayout& layout) const {
    if (!hasImage() || layout.picture.empty()) {
        return;
    }
    const GlBox box = glBox(layout.picture, layout.framebufferHeight);
    glDisable(GL_SCISSOR_TEST); // the blit and the quad both honour the scissor
    if (blitReady_ && width_ == box.width && height_ == box.height) {
        // Texture row 0 (the image's top) is the framebuffer object's bottom row: flip in y.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, width_, height_, box.x, box.y + height_, box.x + width_, box.y,
                          GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return;
    }
    glViewport(box.x, box.y, box.width, box.height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_);
    glUniform2i(viewportOriginLocation_, box.x, box.y);
    glUniform2i(viewportSizeLocation_, box.width, box.height);
    glUniform1i(imageLocation_, 0);
    drawTexturedTriangles(vertexArray_, texture_);
}

Rgba8Image readFramebuffer(int framebufferWidth, int framebufferHeight) {
    Rgba8Image out;
    if (framebufferWidth <= 0 || framebufferHeight <= 0) {
        return out;
    }
    out.width = framebufferWidth;
    out.height = framebufferHeight;
    const std::size_t row = 4 * static_cast<std::size_t>(framebufferWidth);
    std::vector<uint8_t> bottomUp(row * static_cast<std::size_t>(framebufferHeight));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glReadPixels(0, 0, framebufferWidth, framebufferHeight, GL_RGBA, GL_UNSIGNED_BYTE,
                 bottomUp.data());
    // GL's row 0 is the bottom of the framebuffer; images start at the top.
    out.pixels.resize(bottomUp.size());
    for (int y = 0; y < framebufferHeight; ++y) {
        const auto from =
            bottomUp.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y));
        std::copy_n(from, row,
                    out.pixels.begin() +
                        static_cast<std::ptrdiff_t>(
                            row * static_cast<std::size_t>(framebufferHeight - 1 - y)));
    }
    for (std::size_t i = 3; i < out.pixels.size(); i += 4) {
        out.pixels[i] = 255; // the window has no meaningful alpha
    }
    return out;
}

} // namespace raylab::viewer
