#pragma once
// The CPU image on screen: an 8-bit texture holding BGRA data, shown over the picture's box of
// the window's layout (view_layout.h), row 0 of the image at the top, with nearest filtering and
// an exact texel-to-pixel mapping. When the image has the box's size (resolution scale 1), it is
// copied with glBlitFramebuffer (flipped, 1:1) from a framebuffer object holding the texture: on
// Mesa's llvmpipe, with the texture in the window's BGRA order, that is a plain copy
// (PERFORMANCE.md). Otherwise a quad over the box samples it (shaders/quad.frag). Needs a
// current OpenGL 3.3 core context (glad loaded) for its whole life.

#include "io/image_io.h"
#include "view_layout.h"

#include <cstdint>
#include <string>

namespace raylab::viewer {

class ImageQuad {
public:
    ImageQuad() = default;
    ImageQuad(const ImageQuad&) = delete;
    ImageQuad& operator=(const ImageQuad&) = delete;
    ~ImageQuad();

    // Compiles the shaders and creates the texture, its framebuffer object and the vertex array.
    // Returns false with a one-line error.
    bool create(std::string& error);

    // Uploads an image of B, G, R, A bytes (ShownImage::bgra) with glTexSubImage2D; the texture
    // is reallocated only when the size changed. An empty image is ignored.
    void upload(const Rgba8Image& bgraImage);
    bool hasImage() const { return width_ > 0 && height_ > 0; }

    // Draws the image over the layout's picture box of the default framebuffer, every pixel of
    // the box written (no clear needed there when hasImage()); nothing outside it. Leaves the
    // default framebuffer bound for drawing and reading.
    void draw(const ViewLayout& layout) const;

    // Seconds the last upload took (CPU side, including the driver's copy).
    double lastUploadSeconds() const { return uploadSeconds_; }

private:
    unsigned program_ = 0;
    unsigned vertexArray_ = 0;
    unsigned texture_ = 0;
    unsigned framebuffer_ = 0; // reads the texture for the blit
    bool blitReady_ = false;   // the framebuffer object is complete at the texture's size
    int viewportOriginLocation_ = -1;
    int viewportSizeLocation_ = -1;
    int imageLocation_ = -1;
    int width_ = 0;
    int height_ = 0;
    double uploadSeconds_ = 0.0;
};

// Reads the current framebuffer's colour (what was drawn so far this frame) into an RGBA image,
// rows from the top.
Rgba8Image readFramebuffer(int framebufferWidth, int framebufferHeight);

} // namespace raylab::viewer
