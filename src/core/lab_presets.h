#pragma once
// The lab's steps as presets: each sets the settings that reproduce one step of the lab on its box
// (the lab's camera, light and 500 x 500 image), with one line saying what the picture shows and
// which equation applies. A preset sets values; flags given after it override them.

#include "render_settings.h"

#include <span>
#include <string_view>

namespace raylab {

struct LabPreset {
    std::string_view name;     // "lab-4-acne"
    std::string_view shows;    // one line: what the picture shows
    std::string_view equation; // the equation that applies
    void (*apply)(RenderSettings& settings);
};

// The six steps, in the lab's order.
std::span<const LabPreset> labPresets();

// The preset of that name, or null.
const LabPreset* findLabPreset(std::string_view name);

} // namespace raylab
