#include "lab_presets.h"

#include <array>

namespace raylab {

namespace {

// The lab's box as the lab renders it: its camera, light and image, one centred ray a pixel, the
// lab's display. Every step starts here.
RenderSettings labBase() {
    RenderSettings s;
    s.samplesPerPixel = 1;
    return s;
}

void keepThreads(RenderSettings& settings, RenderSettings base) {
    base.threads = settings.threads;
    settings = base;
}

const std::array<LabPreset, 6> kPresets = {{
    {"lab-1-intersection", "each triangle's flat colour where the camera's rays hit it, no light",
     "R = rho",
     [](RenderSettings& s) {
         RenderSettings b = labBase();
         b.view = View::Albedo;
         keepThreads(s, b);
     }},
    {"lab-2-light", "the point light's direct light D alone, no colour and no shadows",
     "D = P max(rhat . nhat, 0) / (4 pi r^2)",
     [](RenderSettings& s) {
         RenderSettings b = labBase();
         b.view = View::Direct;
         b.shadows = false;
         keepThreads(s, b);
     }},
    {"lab-3-diffuse", "diffuse reflection of the direct light, no shadows, no indirect light",
     "R = rho D",
     [](RenderSettings& s) {
         RenderSettings b = labBase();
         b.shadows = false;
         b.indirect = false;
         keepThreads(s, b);
     }},
    {"lab-4-acne",
     "shadows with epsilon = 0: shadow rays hit their own surface, so lit areas are speckled black",
     "R = rho D, D = 0 where a triangle lies at 0 < t < |r|",
     [](RenderSettings& s) {
         RenderSettings b = labBase();
         b.indirect = false;
         b.shadowEpsilon = 0.0f;
         keepThreads(s, b);
     }},
    {"lab-5-shadows", "shadows with the lab's epsilon: the acne is gone, shadows stay black",
     "R = rho D, D = 0 where a triangle lies at eps < t < |r| - eps",
     [](RenderSettings& s) {
         RenderSettings b = labBase();
         b.indirect = false;
         keepThreads(s, b);
     }},
    {"lab-6-indirect", "the constant indirect term lights the shadows: the lab's final picture",
     "R = rho (D + N)", [](RenderSettings& s) { keepThreads(s, labBase()); }},
}};

} // namespace

std::span<const LabPreset> labPresets() { return kPresets; }

const LabPreset* findLabPreset(std::string_view name) {
    for (const LabPreset& preset : kPresets) {
        if (preset.name == name) {
            return &preset;
        }
    }
    return nullptr;
}

} // namespace raylab
