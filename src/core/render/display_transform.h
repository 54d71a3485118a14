#pragma once
// Turns linear radiance into 8-bit display values.

#include "render/framebuffer.h"
#include "render_settings.h"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace raylab {

// One channel to 8 bits. Lab: round(clamp(value, 0, 1) * 255). sRGB: value * 2^exposure through
// the sRGB transfer curve, then the same rounding. NaN maps to 0. (False colour colours a pixel,
// not a channel: for it this is the red byte of a grey pixel of that value; use displayPixel.)
uint8_t displayChannel(float value, DisplayMode mode, float exposure);

// One pixel's three display bytes in any mode: what toRgba8 writes for it.
std::array<uint8_t, 3> displayPixel(const glm::vec3& value, DisplayMode mode, float exposure);

// The order of a display pixel's four bytes: R, G, B, A (image files) or B, G, R, A (the order
// window systems and OpenGL drivers keep, so an upload in it is a plain copy: the viewer's).
enum class PixelOrder { Rgba, Bgra };

// RGBA8 (or BGRA8), row-major from the top-left pixel, alpha 255. `scale` multiplies every pixel
// first (1 / samples for an accumulation buffer of sums); then, for sRGB, 2^exposure. Writes
// exactly toRgba8Scalar's bytes, 8 pixels at a time with AVX2 where the CPU has it.
void toRgba8(std::span<const glm::vec3> linear, float scale, DisplayMode mode, float exposure,
             std::span<uint8_t> rgba, PixelOrder order = PixelOrder::Rgba);
// The reference: each channel of linear[i] * scale through displayChannel, pixel by pixel.
void toRgba8Scalar(std::span<const glm::vec3> linear, float scale, DisplayMode mode, float exposure,
                   std::span<uint8_t> rgba, PixelOrder order = PixelOrder::Rgba);
std::vector<uint8_t> toRgba8(const Framebuffer& image, DisplayMode mode, float exposure);

} // namespace raylab
