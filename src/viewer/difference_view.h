#pragma once
// The compare's third mode besides the wipe and the flip: the signed difference of the split's two
// sides, left - right (live - A when A is a snapshot), from their linear means (films), shown on
// a diverging colour scale. GL-free; the render thread composes it (render_worker.h).
//
// The scale: a pixel's value is d = the mean of its three channels' differences (W/m^2), and
// t = clamp(d / scale, -1, 1) is shown as R, G, B = (round(255 t), 0, 0) for t >= 0 (red: live is
// brighter) and (0, 0, round(-255 t)) for t < 0 (blue: live is darker). Black: no difference.

#include "core/render/display_transform.h"
#include "core/render/framebuffer.h"

#include <array>
#include <cstdint>
#include <span>

namespace raylab::viewer {

enum class CompareMode {
    Wipe,       // left of the divider one side, right of it the other (F held: the right side)
    Difference, // left - right over the whole picture
};

const char* toString(CompareMode mode); // "wipe", "difference"

// The value (W/m^2) shown in full colour at first, and the scale slider's range.
inline constexpr float kDefaultDifferenceScale = 0.1f;
inline constexpr float kMinDifferenceScale = 1e-4f;
inline constexpr float kMaxDifferenceScale = 100.0f;

// R, G, B of the value d (W/m^2) at `scale` (> 0), as above.
std::array<uint8_t, 3> differenceColour(float d, float scale);

// difference = left - right per pixel and channel; bytes (4 a pixel, in `order`, alpha 255) =
// differenceColour of each pixel's mean difference. left and right have one size; bytes holds
// 4 * width * height bytes.
void composeDifference(const Framebuffer& left, const Framebuffer& right, float scale,
                       Framebuffer& difference, std::span<uint8_t> bytes, PixelOrder order);

} // namespace raylab::viewer
