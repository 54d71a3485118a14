#include "difference_view.h"

#include <algorithm>
#include <cmath>

namespace raylab::viewer {

const char* toString(CompareMode mode) {
    return mode == CompareMode::Difference ? "difference" : "wipe";
}

std::array<uint8_t, 3> differenceColour(float d, float scale) {
    const float t = std::clamp(d / scale, -1.0f, 1.0f);
    if (std::isnan(t)) { // a NaN value: shown as no difference
        return {0, 0, 0};
    }
    const auto level = static_cast<uint8_t>(std::lround(255.0f * std::abs(t)));
    return t >= 0.0f ? std::array<uint8_t, 3>{level, 0, 0} : std::array<uint8_t, 3>{0, 0, level};
}

void composeDifference(const Framebuffer& left, const Framebuffer& right, float scale,
                       Framebuffer& difference, std::span<uint8_t> bytes, PixelOrder order) {
    difference.width = left.width;
    difference.height = left.height;
    difference.pixels.resize(left.pixels.size());
    const std::size_t red = order == PixelOrder::Rgba ? 0 : 2;
    for (std::size_t i = 0; i < left.pixels.size(); ++i) {
        const glm::vec3 d = left.pixels[i] - right.pixels[i];
        difference.pixels[i] = d;
        const std::array<uint8_t, 3> rgb = differenceColour((d.x + d.y + d.z) / 3.0f, scale);
        uint8_t* out = bytes.data() + 4 * i;
        out[red] = rgb[0];
        out[1] = rgb[1];
        out[2 - red] = rgb[2];
        out[3] = 255;
    }
}

} // namespace raylab::viewer
