#include "display_transform.h"

#include "srgb_quantizer.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace raylab {

namespace {

// round(clamp(unit, 0, 1) * 255), NaN to 0; branch-free so the loops below vectorise.
inline uint8_t quantize(float unit) {
    const float clamped = std::min(unit > 0.0f ? unit : 0.0f, 1.0f);
    return static_cast<uint8_t>(clamped * 255.0f + 0.5f);
}

} // namespace

uint8_t displayChannel(float value, DisplayMode mode, float exposure) {
    if (mode == DisplayMode::Lab) {
        return quantize(value);
    }
    return srgbQuantizer()(value * std::exp2(exposure));
}

void toRgba8(std::span<const glm::vec3> linear, float scale, DisplayMode mode, float exposure,
             std::span<uint8_t> rgba) {
    assert(rgba.size() >= 4 * linear.size());
    if (mode == DisplayMode::Lab) {
        for (std::size_t i = 0; i < linear.size(); ++i) {
            const glm::vec3 c = linear[i] * scale;
            rgba[4 * i + 0] = quantize(c.x);
            rgba[4 * i + 1] = quantize(c.y);
            rgba[4 * i + 2] = quantize(c.z);
            rgba[4 * i + 3] = 255;
        }
        return;
    }
    const SrgbQuantizer& srgb = srgbQuantizer();
    const float gain = std::exp2(exposure);
    for (std::size_t i = 0; i < linear.size(); ++i) {
        const glm::vec3 c = linear[i] * scale;
        rgba[4 * i + 0] = srgb(c.x * gain);
        rgba[4 * i + 1] = srgb(c.y * gain);
        rgba[4 * i + 2] = srgb(c.z * gain);
        rgba[4 * i + 3] = 255;
    }
}

std::vector<uint8_t> toRgba8(const Framebuffer& image, DisplayMode mode, float exposure) {
    std::vector<uint8_t> rgba(4 * image.pixels.size());
    toRgba8(image.pixels, 1.0f, mode, exposure, rgba);
    return rgba;
}

} // namespace raylab
