#include "display_transform.h"

#include <cassert>
#include <cmath>

namespace raylab {

namespace {

uint8_t quantize(float unit) {
    // !(unit > 0) also catches NaN.
    if (!(unit > 0.0f)) {
        return 0;
    }
    if (unit >= 1.0f) {
        return 255;
    }
    return static_cast<uint8_t>(unit * 255.0f + 0.5f);
}

float srgbEncode(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

} // namespace

uint8_t displayChannel(float value, DisplayMode mode, float exposure) {
    if (mode == DisplayMode::Lab) {
        return quantize(value);
    }
    const float exposed = value * std::exp2(exposure);
    return quantize(exposed > 0.0f ? srgbEncode(exposed) : 0.0f);
}

void toRgba8(std::span<const glm::vec3> linear, float scale, DisplayMode mode, float exposure,
             std::span<uint8_t> rgba) {
    assert(rgba.size() >= 4 * linear.size());
    for (std::size_t i = 0; i < linear.size(); ++i) {
        const glm::vec3 c = linear[i] * scale;
        rgba[4 * i + 0] = displayChannel(c.x, mode, exposure);
        rgba[4 * i + 1] = displayChannel(c.y, mode, exposure);
        rgba[4 * i + 2] = displayChannel(c.z, mode, exposure);
        rgba[4 * i + 3] = 255;
    }
}

std::vector<uint8_t> toRgba8(const Framebuffer& image, DisplayMode mode, float exposure) {
    std::vector<uint8_t> rgba(4 * image.pixels.size());
    toRgba8(image.pixels, 1.0f, mode, exposure, rgba);
    return rgba;
}

} // namespace raylab
