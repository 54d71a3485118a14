#pragma once
// The panel's pixels, kept between frames. On a software GL driver (llvmpipe) Dear ImGui's many
// small draw calls cost 3-4 ms of CPU a frame at 1280 x 720, whether or not the panel changed.
// PanelCache renders the frame's draw data into an offscreen RGBA8 texture (premultiplied
// alpha: ImGui's own blending into a transparent target gives exactly that) only when its
// signature (panel_signature.h: every vertex, index, clip rectangle and texture, and the display
// size) differs from the last one rendered, or the framebuffer's size changed; every frame it
// then composites the texture over the default framebuffer with one blended triangle restricted
// to the panel's bounds (source "one", destination "one minus source alpha"). Outside the bounds
// no pixel is touched; inside, the result is ImGui's drawn directly, up to 8-bit rounding.
// Needs a current OpenGL 3.3 core context (glad loaded) and ImGui's OpenGL3 backend initialised
// for its whole life. Used through PanelLayer (panel_layer.h).

#include "panel_signature.h"

#include <string>

struct ImDrawData;

namespace raylab::viewer {

class PanelCache {
public:
    PanelCache() = default;
    PanelCache(const PanelCache&) = delete;
    PanelCache& operator=(const PanelCache&) = delete;
    ~PanelCache();

    // Compiles the compositing shader and creates the texture, its framebuffer object and the
    // vertex array. Returns false with a one-line error.
    bool create(std::string& error);

    // Draws `data` (this frame's ImGui::GetDrawData()) over the default framebuffer of
    // framebufferWidth x framebufferHeight pixels (nothing when a side is 0), re-rendering the
    // cache first when needed. Leaves the default framebuffer bound, blending and scissor off
    // and the viewport at the whole framebuffer.
    void draw(ImDrawData& data, int framebufferWidth, int framebufferHeight);

    // Frames drawn by draw() so far, and how many of them re-rendered the cache.
    long framesDrawn() const { return framesDrawn_; }
    long rerenders() const { return rerenders_; }

private:
    // Gives the texture the framebuffer's size (cleared to transparent). False when the
    // framebuffer object is not complete: draw() then draws ImGui directly.
    bool fitTexture(int width, int height);

    unsigned program_ = 0;
    int rectLocation_ = -1;
    unsigned vertexArray_ = 0;
    unsigned texture_ = 0;
    unsigned framebuffer_ = 0; // draws into texture_
    int width_ = 0;            // texture_'s size; 0: not allocated
    int height_ = 0;
    bool complete_ = false;
    bool valid_ = false; // texture_ holds the draw data of `last_`
    PanelSignature last_;
    long framesDrawn_ = 0;
    long rerenders_ = 0;
};

} // namespace raylab::viewer
