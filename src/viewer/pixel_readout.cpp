#include "pixel_readout.h"

#include <algorithm>
#include <glm/vec3.hpp>

namespace raylab::viewer {

std::optional<PixelReadout> readPixel(const ShownImage& shown, int x, int y) {
    const Framebuffer& linear = shown.linear;
    if (shown.preview || linear.width != shown.bgra.width || linear.height != shown.bgra.height ||
        x < 0 || y < 0 || x >= linear.width || y >= linear.height) {
        return std::nullopt;
    }
    PixelReadout out;
    out.x = x;
    out.y = y;
    out.linear = linear.at(x, y);
    // ShownImage::bgra holds B, G, R, A.
    const std::size_t at =
        4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(linear.width) +
             static_cast<std::size_t>(x));
    out.display = {shown.bgra.pixels[at + 2], shown.bgra.pixels[at + 1], shown.bgra.pixels[at]};
    return out;
}

std::optional<RectangleMean> rectangleMean(const Framebuffer& linear,
                                           const PixelRectangle& rectangle) {
    PixelRectangle r;
    r.x0 = std::max(std::min(rectangle.x0, rectangle.x1), 0);
    r.x1 = std::min(std::max(rectangle.x0, rectangle.x1), linear.width - 1);
    r.y0 = std::max(std::min(rectangle.y0, rectangle.y1), 0);
    r.y1 = std::min(std::max(rectangle.y0, rectangle.y1), linear.height - 1);
    if (r.x0 > r.x1 || r.y0 > r.y1) {
        return std::nullopt;
    }
    glm::dvec3 sum(0.0);
    for (int y = r.y0; y <= r.y1; ++y) {
        for (int x = r.x0; x <= r.x1; ++x) {
            sum += glm::dvec3(linear.at(x, y));
        }
    }
    RectangleMean out;
    out.rectangle = r;
    out.pixels = static_cast<long>(r.x1 - r.x0 + 1) * static_cast<long>(r.y1 - r.y0 + 1);
    out.mean = sum / static_cast<double>(out.pixels);
    return out;
}

} // namespace raylab::viewer
