#include "render/false_colour.h"

#include <algorithm>
#include <cmath>

namespace raylab {
namespace {

// The scale's colours at evenly spaced positions, bytes: dark blue to white through blue, cyan,
// green, yellow and red, so that brighter always reads as warmer and each band is distinct.
constexpr std::array<std::array<uint8_t, 3>, 7> kRamp = {{
    {0, 0, 64},
    {0, 64, 255},
    {0, 224, 255},
    {32, 200, 64},
    {255, 230, 0},
    {255, 32, 0},
    {255, 255, 255},
}};

} // namespace

float falseColourPosition(float value, float exposure) {
    if (!(value > 0.0f)) {
        return -1.0f;
    }
    const float t = (std::log2(value) - exposure) / kFalseColourStops + 0.5f;
    return std::clamp(t, 0.0f, 1.0f);
}

std::array<uint8_t, 3> falseColourAt(float t) {
    const float x = std::clamp(t, 0.0f, 1.0f) * static_cast<float>(kRamp.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(x), kRamp.size() - 2);
    const float f = x - static_cast<float>(i);
    std::array<uint8_t, 3> out{};
    for (std::size_t c = 0; c < 3; ++c) {
        const float a = kRamp[i][c];
        const float b = kRamp[i + 1][c];
        out[c] = static_cast<uint8_t>(a + (b - a) * f + 0.5f);
    }
    return out;
}

std::array<uint8_t, 3> falseColour(const glm::vec3& value, float exposure) {
    const float largest = std::max({value.x, value.y, value.z});
    const float t = falseColourPosition(largest, exposure);
    return t < 0.0f ? std::array<uint8_t, 3>{0, 0, 0} : falseColourAt(t);
}

float falseColourValue(float t, float exposure) {
    return std::exp2(exposure + (t - 0.5f) * kFalseColourStops);
}

} // namespace raylab
