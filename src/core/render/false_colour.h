#pragma once
// The false-colour display: a pixel's value on a logarithmic colour scale, for pictures whose
// values lie far outside [0, 1] (an emitter beside a dark corner, the cost view, a direct term
// of hundreds of W/m^2). The value shown is the largest of the pixel's three channels; the scale
// spans kFalseColourStops stops (factors of 2) centred on 2^exposure: 2^(exposure - 8) is the
// scale's dark end, 2^exposure its middle, 2^(exposure + 8) its bright end. Zero, negative and NaN
// values are black; values past the ends take the end colours.

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace raylab {

inline constexpr float kFalseColourStops = 16.0f;

// The position of `value` on the scale, in [0, 1]; negative when it has no colour (<= 0 or NaN).
float falseColourPosition(float value, float exposure);

// The colour at position t in [0, 1] (dark blue, blue, cyan, green, yellow, red, white), bytes.
std::array<uint8_t, 3> falseColourAt(float t);

// The bytes of one pixel: falseColourAt of its largest channel, black when it has no colour.
std::array<uint8_t, 3> falseColour(const glm::vec3& value, float exposure);

// The value at position t of the scale: 2^(exposure + (t - 0.5) * kFalseColourStops). For legends.
float falseColourValue(float t, float exposure);

} // namespace raylab
