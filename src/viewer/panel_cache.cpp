#include "panel_cache.h"

#include "gl_program.h"

#include <glad/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace raylab::viewer {

namespace {

// Two triangles that cover the viewport exactly (llvmpipe draws such a rectangle on its fast
// path), with the texture coordinates of uRect at its corners.
const char* const kVertexShader = R"(#version 330 core
const vec2 kCorners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
                                 vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
uniform vec4 uRect; // the viewport in texture coordinates: x0, y0, x1, y1
out vec2 texCoord;
void main() {
    vec2 corner = kCorners[gl_VertexID];
    texCoord = mix(uRect.xy, uRect.zw, corner);
    gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
}
)";

// The texture has the framebuffer's size and orientation: texel = window pixel, 1:1.
const char* const kFragmentShader = R"(#version 330 core
uniform sampler2D uPanel;
in vec2 texCoord;
out vec4 fragColor;
void main() { fragColor = texture(uPanel, texCoord); }
)";

// Sets the scissor to a rectangle given with rows from the top, in a framebuffer of `height`.
void scissorTo(const PixelRect& r, int height) {
    glScissor(r.x0, height - r.y1, r.x1 - r.x0, r.y1 - r.y0);
}

} // namespace

PanelCache::~PanelCache() { deleteGlObjects(program_, vertexArray_, texture_, framebuffer_); }

bool PanelCache::create(std::string& error) {
    program_ =
        buildProgram(kVertexShader, kFragmentShader, "the panel's compositing shader", error);
    if (program_ == 0) {
        return false;
    }
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "uPanel"), 0);
    rectLocation_ = glGetUniformLocation(program_, "uRect");
    glUseProgram(0);
    glGenVertexArrays(1, &vertexArray_);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &framebuffer_);
    return true;
}

bool PanelCache::fitTexture(int width, int height) {
    if (width == width_ && height == height_) {
        return complete_;
    }
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    width_ = width;
    height_ = height;
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    complete_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (complete_) {
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    valid_ = false;
    last_ = PanelSignature{};
    return complete_;
}

void PanelCache::draw(ImDrawData& data, int framebufferWidth, int framebufferHeight) {
    if (framebufferWidth <= 0 || framebufferHeight <= 0) {
        return;
    }
    ++framesDrawn_;
    if (!fitTexture(framebufferWidth, framebufferHeight)) {
        ImGui_ImplOpenGL3_RenderDrawData(&data); // no cache: draw directly
        ++rerenders_;
        return;
    }
    const PanelSignature signature = panelSignature(data);
    if (!valid_ || signature != last_) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        // Only what the last panel covered can hold pixels: clear that, then draw the new one.
        const PixelRect stale = last_.bounds;
        if (!stale.empty()) {
            glEnable(GL_SCISSOR_TEST);
            scissorTo(stale, framebufferHeight);
            glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glDisable(GL_SCISSOR_TEST);
        }
        ImGui_ImplOpenGL3_RenderDrawData(&data);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        last_ = signature;
        valid_ = true;
        ++rerenders_;
    }
    const PixelRect& r = last_.bounds;
    if (!r.empty()) {
        glViewport(r.x0, framebufferHeight - r.y1, r.x1 - r.x0, r.y1 - r.y0);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glUseProgram(program_);
        const float w = static_cast<float>(framebufferWidth),
                    h = static_cast<float>(framebufferHeight);
        glUniform4f(rectLocation_, static_cast<float>(r.x0) / w,
                    static_cast<float>(framebufferHeight - r.y1) / h, static_cast<float>(r.x1) / w,
                    static_cast<float>(framebufferHeight - r.y0) / h);
        drawTexturedTriangles(vertexArray_, texture_);
        glDisable(GL_BLEND);
    }
    glViewport(0, 0, framebufferWidth, framebufferHeight);
}

} // namespace raylab::viewer
