#include "render_settings.h"

#include "finite.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <iterator>
#include <sstream>
#include <utility>

namespace raylab {

namespace {

bool isFiniteNonNegative(const glm::vec3& v) {
    return isFinite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

std::string text(float value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

std::string text(const glm::vec3& v) { return text(v.x) + "," + text(v.y) + "," + text(v.z); }

std::string text(int value) { return std::to_string(value); }
std::string text(bool value) { return value ? "on" : "off"; }
std::string text(DisplayMode mode) { return toString(mode); }
std::string text(SamplerKind kind) { return toString(kind); }

} // namespace

std::vector<std::string> settingsDifferences(const RenderSettings& a, const RenderSettings& b) {
    std::vector<std::string> out;
    const auto field = [&out](const char* name, const auto& x, const auto& y) {
        if (!(x == y)) {
            out.push_back(std::string(name) + " " + text(x) + " -> " + text(y));
        }
    };
    field("camera position", a.camera.position, b.camera.position);
    field("yaw", a.camera.yawDegrees, b.camera.yawDegrees);
    field("pitch", a.camera.pitchDegrees, b.camera.pitchDegrees);
    field("field of view", a.camera.verticalFovDegrees, b.camera.verticalFovDegrees);
    field("light position", a.light.position, b.light.position);
    field("light colour", a.light.color, b.light.color);
    field("light power", a.light.intensity, b.light.intensity);
    field("light radius", a.light.radius, b.light.radius);
    field("indirect", a.indirect, b.indirect);
    field("indirect colour", a.indirectColor, b.indirectColor);
    field("indirect N", a.indirectIntensity, b.indirectIntensity);
    field("shadows", a.shadows, b.shadows);
    field("shadow epsilon", a.shadowEpsilon, b.shadowEpsilon);
    field("width", a.width, b.width);
    field("height", a.height, b.height);
    field("sample cap", a.samplesPerPixel, b.samplesPerPixel);
    field("threads", a.threads, b.threads);
    field("display", a.display, b.display);
    field("exposure", a.exposure, b.exposure);
    if (a.integrator != b.integrator) {
        out.push_back(std::string("integrator ") + toString(a.integrator) + " -> " +
                      toString(b.integrator));
    }
    field("max bounces", a.maxBounces, b.maxBounces);
    field("emission scale", a.emissionScale, b.emissionScale);
    field("sampler", a.sampler, b.sampler);
    if (a.view != b.view) {
        out.push_back(std::string("view ") + toString(a.view) + " -> " + toString(b.view));
    }
    return out;
}

std::string validate(const RenderSettings& s) {
    const Camera& c = s.camera;
    if (!isFinite(c.position)) {
        return "camera position must be finite, got " + text(c.position);
    }
    if (!std::isfinite(c.yawDegrees)) {
        return "camera yaw must be finite, got " + text(c.yawDegrees);
    }
    if (!(c.pitchDegrees > -90.0f && c.pitchDegrees < 90.0f)) {
        return "camera pitch must be in (-90, 90) degrees, got " + text(c.pitchDegrees);
    }
    if (!(c.verticalFovDegrees > 0.0f && c.verticalFovDegrees < 180.0f)) {
        return "field of view must be in (0, 180) degrees, got " + text(c.verticalFovDegrees);
    }
    if (!isFinite(s.light.position)) {
        return "light position must be finite, got " + text(s.light.position);
    }
    if (!isFiniteNonNegative(s.light.color)) {
        return "light colour must be finite and >= 0, got " + text(s.light.color);
    }
    if (!(std::isfinite(s.light.intensity) && s.light.intensity >= 0.0f)) {
        return "light power must be finite and >= 0, got " + text(s.light.intensity);
    }
    if (!(std::isfinite(s.light.radius) && s.light.radius >= 0.0f)) {
        return "light radius must be finite and >= 0, got " + text(s.light.radius);
    }
    if (!isFiniteNonNegative(s.indirectColor)) {
        return "indirect colour must be finite and >= 0, got " + text(s.indirectColor);
    }
    if (!(std::isfinite(s.indirectIntensity) && s.indirectIntensity >= 0.0f)) {
        return "indirect light must be finite and >= 0, got " + text(s.indirectIntensity);
    }
    if (!(std::isfinite(s.shadowEpsilon) && s.shadowEpsilon >= 0.0f)) {
        return "shadow epsilon must be finite and >= 0, got " + text(s.shadowEpsilon);
    }
    if (s.width < 1 || s.width > kMaxImageSide || s.height < 1 || s.height > kMaxImageSide) {
        return "image size must be 1.." + std::to_string(kMaxImageSide) + " on each side, got " +
               std::to_string(s.width) + "x" + std::to_string(s.height);
    }
    if (s.samplesPerPixel < 1 || s.samplesPerPixel > kMaxSamplesPerPixel) {
        return "samples per pixel must be 1.." + std::to_string(kMaxSamplesPerPixel) + ", got " +
               std::to_string(s.samplesPerPixel);
    }
    if (s.threads < 0 || s.threads > kMaxThreads) {
        return "threads must be 0 (all) .. " + std::to_string(kMaxThreads) + ", got " +
               std::to_string(s.threads);
    }
    if (!(std::isfinite(s.exposure) && std::abs(s.exposure) <= 64.0f)) {
        return "exposure must be finite within [-64, 64] stops, got " + text(s.exposure);
    }
    if (s.maxBounces < 0 || s.maxBounces > kMaxBounces) {
        return "max bounces must be 0.." + std::to_string(kMaxBounces) + ", got " +
               std::to_string(s.maxBounces);
    }
    if (!(std::isfinite(s.emissionScale) && s.emissionScale >= 0.0f)) {
        return "emission scale must be finite and >= 0, got " + text(s.emissionScale);
    }
    return {};
}

void splitColourIntensity(const glm::vec3& rgb, glm::vec3& colour, float& intensity) {
    const float peak = std::max({rgb.x, rgb.y, rgb.z});
    if (!(peak > 0.0f)) {
        colour = glm::vec3(1.0f);
        intensity = 0.0f;
        return;
    }
    colour = glm::min(rgb / peak, glm::vec3(1.0f));
    intensity = peak;
}

bool sameSamples(const RenderSettings& a, const RenderSettings& b) {
    RenderSettings x = a;
    x.samplesPerPixel = b.samplesPerPixel;
    x.threads = b.threads;
    x.display = b.display;
    x.exposure = b.exposure;
    return x == b;
}

const char* toString(DisplayMode mode) {
    switch (mode) {
    case DisplayMode::Lab: return "lab";
    case DisplayMode::Srgb: return "srgb";
    case DisplayMode::FalseColour: return "false-colour";
    }
    return "lab";
}

bool parseDisplayMode(const std::string& text, DisplayMode& mode) {
    if (text == "lab") {
        mode = DisplayMode::Lab;
        return true;
    }
    if (text == "srgb") {
        mode = DisplayMode::Srgb;
        return true;
    }
    if (text == "false-colour" || text == "false-color") {
        mode = DisplayMode::FalseColour;
        return true;
    }
    return false;
}

} // namespace raylab

namespace raylab {

const char* toString(Integrator integrator) {
    return integrator == Integrator::Lab ? "lab" : "path";
}

bool parseIntegrator(const std::string& text, Integrator& integrator) {
    if (text == "lab") {
        integrator = Integrator::Lab;
        return true;
    }
    if (text == "path") {
        integrator = Integrator::Path;
        return true;
    }
    return false;
}

} // namespace raylab

namespace raylab {

namespace {
constexpr std::pair<View, const char*> kViewNames[] = {
    {View::Beauty, "beauty"},         {View::Albedo, "albedo"},
    {View::Direct, "direct"},         {View::Indirect, "indirect"},
    {View::Visibility, "visibility"}, {View::Normal, "normal"},
    {View::Depth, "depth"},           {View::Cost, "cost"},
};
} // namespace

const char* toString(View view) {
    for (const auto& [v, name] : kViewNames) {
        if (v == view) {
            return name;
        }
    }
    return "beauty";
}

View nextView(View view, int step) {
    constexpr int count = static_cast<int>(std::size(kViewNames));
    int index = 0;
    while (index < count && kViewNames[index].first != view) {
        ++index;
    }
    return kViewNames[((index + step) % count + count) % count].first;
}

bool parseView(const std::string& text, View& view) {
    for (const auto& [v, name] : kViewNames) {
        if (text == name) {
            view = v;
            return true;
        }
    }
    return false;
}

} // namespace raylab
