#pragma once
// Everything that decides a picture besides the scene: one plain struct with the lab's defaults.
// The viewer's panel, raylab-render's flags and the settings JSON all edit this struct.

#include "camera.h"

#include <glm/vec3.hpp>
#include <string>

namespace raylab {

enum class DisplayMode {
    Lab,  // the lab's display: clamp(R, 0, 1) * 255, no gamma
    Srgb, // R * 2^exposure, then the sRGB transfer curve
};

// A point light. Its power P = color * intensity, in watts per colour channel.
struct PointLight {
    glm::vec3 position{0.0f, 0.5f, -0.7f}; // the lab's (0, -0.5, -0.7) in y-up world
    glm::vec3 color{1.0f};                 // each channel >= 0; the panel keeps it in [0, 1]
    float intensity = 14.0f;               // >= 0
    glm::vec3 power() const { return color * intensity; }

    bool operator==(const PointLight&) const = default;
};

struct RenderSettings {
    Camera camera;
    PointLight light;

    // The lab's constant indirect term N = indirectColor * indirectIntensity (radiance units).
    bool indirect = true;
    glm::vec3 indirectColor{1.0f};
    float indirectIntensity = 0.5f;

    // Shadow rays start at the hit point and count blockers with epsilon < t < |r| - epsilon
    // (world units). 0 shows the lab's shadow acne.
    bool shadows = true;
    float shadowEpsilon = 1e-3f;

    int width = 500;         // pixels, 1..kMaxImageSide
    int height = 500;        // pixels, 1..kMaxImageSide
    int samplesPerPixel = 1; // 1 = the lab's single centred ray; more = jittered and averaged
    int threads = 0;         // 0 = every hardware thread

    DisplayMode display = DisplayMode::Lab;
    float exposure = 0.0f; // stops, for DisplayMode::Srgb

    glm::vec3 indirect3() const {
        return indirect ? indirectColor * indirectIntensity : glm::vec3(0.0f);
    }

    // Every field equal (valid settings hold no NaN).
    bool operator==(const RenderSettings&) const = default;
};

inline constexpr int kMaxImageSide = 16384;
inline constexpr int kMaxSamplesPerPixel = 1 << 16;
inline constexpr int kMaxThreads = 1024;

// Returns an empty string when every value makes sense, otherwise one line naming the first
// value that does not (e.g. "light intensity must be finite and >= 0, got nan").
std::string validate(const RenderSettings& settings);

const char* toString(DisplayMode mode);
// Parses "lab" or "srgb"; returns false for anything else.
bool parseDisplayMode(const std::string& text, DisplayMode& mode);

} // namespace raylab
