#pragma once
// What the panel reads off the picture shown (GL-free): the pixel under the cursor, its linear
// value (the film's mean, ShownImage::linear: R per channel, W/m^2, or live - A in the difference
// view) and its displayed bytes (0-255), and the mean linear value of a rectangle of pixels
// (Shift + left drag).

#include "shown_image.h"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>

namespace raylab::viewer {

struct PixelReadout {
    int x = 0, y = 0;                        // picture pixels, y down
    glm::vec3 linear{0.0f};                  // ShownImage::linear at (x, y)
    std::array<uint8_t, 3> display{0, 0, 0}; // R, G, B as shown
};

// Picture pixels x0..x1 by y0..y1, both ends included, in either order.
struct PixelRectangle {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool operator==(const PixelRectangle&) const = default;
};

struct RectangleMean {
    PixelRectangle rectangle; // ordered (x0 <= x1, y0 <= y1) and inside the picture
    long pixels = 0;
    glm::dvec3 mean{0.0}; // the mean of the linear values, per channel
};

// Pixel (x, y) of `shown`; nullopt outside the picture or when it has no linear picture (a
// preview, or a job that did not keep one).
std::optional<PixelReadout> readPixel(const ShownImage& shown, int x, int y);

// The mean of `linear` over the part of `rectangle` inside it; nullopt when nothing is inside.
std::optional<RectangleMean> rectangleMean(const Framebuffer& linear,
                                           const PixelRectangle& rectangle);

} // namespace raylab::viewer
