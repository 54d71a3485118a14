#pragma once
// Everything that decides a picture besides the scene: one plain struct with the lab's defaults.
// The viewer's panel, raylab-render's flags and the settings JSON all edit this struct.

#include "camera.h"
#include "sampling/sampler.h"

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace raylab {

enum class DisplayMode {
    Lab,         // the lab's display: clamp(R, 0, 1) * 255, no gamma
    Srgb,        // R * 2^exposure, then the sRGB transfer curve
    FalseColour, // the largest channel on a logarithmic colour scale about 2^exposure
                 // (render/false_colour.h)
};

// Which light transport makes the picture (DESIGN.md section 5).
enum class Integrator {
    Lab,  // R = E + rho * (D + N) with the constant N: the lab's model
    Path, // R = E + rho * (D + N(x)) with N(x) computed by Monte Carlo path tracing
};

// What the picture shows: the lit picture, or one term of the light model on its own.
enum class View {
    Beauty,     // R
    Albedo,     // rho
    Direct,     // D, shadows applied, before rho
    Indirect,   // N: the lab's constant, or the path integrator's estimate
    Visibility, // the fraction of the light the point sees: 0 in shadow, between in a penumbra
    Normal,     // the facing normal, n * 0.5 + 0.5
    Depth,      // t along the camera ray, in world units
    Cost,       // BVH nodes visited and triangles tested for the camera and shadow rays, as a
                // heat colour (heatColor of costHeat, term_views.h)
};

// The lab's light. Its power P = color * intensity, in watts per colour channel. With radius 0 it
// is the lab's point light; with radius r > 0 it is a sphere of radius r centred at position,
// emitting the same total power uniformly from its surface (soft shadows). The sphere is not
// geometry: rays pass through it, and it lights the scene only through its samples.
struct PointLight {
    glm::vec3 position{0.0f, 0.5f, -0.7f}; // the lab's (0, -0.5, -0.7) in y-up world
    glm::vec3 color{1.0f};                 // each channel >= 0; the panel keeps it in [0, 1]
    float intensity = 14.0f;               // >= 0; 0 leaves a scene lit by its emitters alone
    float radius = 0.0f;                   // world units, >= 0
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
    float exposure = 0.0f; // stops, for DisplayMode::Srgb and FalseColour

    Integrator integrator = Integrator::Lab;
    // The path integrator's indirect bounces (0 = direct light only), with Russian roulette from
    // the fourth on. `indirect` off means 0 too.
    int maxBounces = 8;
    // Multiplies the emission (Le) of every emitting material of the scene; >= 0.
    float emissionScale = 1.0f;
    SamplerKind sampler = SamplerKind::Sobol; // the path integrator's and the sphere light's
    View view = View::Beauty;

    glm::vec3 indirect3() const {
        return indirect ? indirectColor * indirectIntensity : glm::vec3(0.0f);
    }

    // Every field equal (valid settings hold no NaN).
    bool operator==(const RenderSettings&) const = default;
};

inline constexpr int kMaxImageSide = 16384;
inline constexpr int kMaxSamplesPerPixel = 1 << 16;
inline constexpr int kMaxThreads = 1024;
inline constexpr int kMaxBounces = 1024;

// An RGB value as a colour and an intensity, the way the settings keep the light's power and the
// indirect constant: intensity = the largest channel, colour = rgb / intensity (white with
// intensity 0 for black). Every channel must be finite and >= 0.
void splitColourIntensity(const glm::vec3& rgb, glm::vec3& colour, float& intensity);

// The fields in which b differs from a, one short line each ("shadow epsilon 0.001 -> 0"), in
// the struct's order; empty when they are equal. For the viewer's comparison of two pictures.
std::vector<std::string> settingsDifferences(const RenderSettings& a, const RenderSettings& b);

// True when two settings give the same samples, so that a film of one can go on accumulating
// for the other: every field but the sample cap, the thread count and the display transform.
// The one rule for when a progressive picture restarts.
bool sameSamples(const RenderSettings& a, const RenderSettings& b);

// Returns an empty string when every value makes sense, otherwise one line naming the first
// value that does not (e.g. "light intensity must be finite and >= 0, got nan").
std::string validate(const RenderSettings& settings);

const char* toString(DisplayMode mode);
// Parses "lab" or "srgb"; returns false for anything else.
bool parseDisplayMode(const std::string& text, DisplayMode& mode);
const char* toString(Integrator integrator);
const char* toString(View view);
// The view `step` places after `view` in the order above, wrapping around (V and Shift+V).
View nextView(View view, int step);
// Parses a view's name (beauty, albedo, direct, indirect, visibility, normal, depth).
bool parseView(const std::string& text, View& view);
// Parses "lab" or "path"; returns false for anything else.
bool parseIntegrator(const std::string& text, Integrator& integrator);

} // namespace raylab
