#include "settings_edit.h"

#include "core/scene_framing.h"

#include <algorithm>
#include <cmath>

namespace raylab::viewer {

bool acceptEdit(const RenderSettings& edited, RenderSettings& current, std::string& why) {
    why = validate(edited);
    if (!why.empty()) {
        return false;
    }
    current = edited;
    return true;
}

float epsilonFromSlider(float t, float maxEpsilon) {
    if (!(t > 0.0f)) {
        return 0.0f;
    }
    return maxEpsilon * std::pow(10.0f, -kEpsilonDecades * (1.0f - std::min(t, 1.0f)));
}

float sliderFromEpsilon(float epsilon, float maxEpsilon) {
    if (!(epsilon > 0.0f) || !(maxEpsilon > 0.0f)) {
        return 0.0f;
    }
    const float t = 1.0f + std::log10(epsilon / maxEpsilon) / kEpsilonDecades;
    // A tiny non-zero epsilon below the scale stays just right of the zero position.
    return std::clamp(t, 1e-4f, 1.0f);
}

void resetToLabDefaults(const Scene& scene, bool isLabBox, RenderSettings& settings) {
    RenderSettings lab;
    lab.width = settings.width;
    lab.height = settings.height;
    lab.samplesPerPixel = settings.samplesPerPixel;
    lab.threads = settings.threads;
    if (!isLabBox) {
        frameScene(scene, lab);
    }
    settings = lab;
}

void placeForScene(const Scene& scene, bool isLabBox, RenderSettings& settings) {
    raylab::placeForScene(scene, isLabBox, GivenSettings{}, settings);
}

} // namespace raylab::viewer
