#pragma once
// The lab's Cornell box: 30 triangles built from the lab's original numbers (L = 555), scaled
// with v * 2/L - 1 into [-1, 1]^3, y up, without the lab's x and y flips (together a half-turn
// about z, so the picture is the same).

#include "scene.h"

#include <string_view>

namespace raylab {

// The lab's box's name where the programs take a scene (SCENE, the panel's path field, settings
// files): any other name is a mesh file.
inline constexpr std::string_view kLabBoxName = "cornell";
inline bool isLabBoxName(std::string_view name) { return name == kLabBoxName; }

// Triangle order: floor (2), left wall (2), right wall (2), ceiling (2), back wall (2),
// short block (10), tall block (10). Materials: one per colour, in the order of LabColor.
Scene makeCornellBox();

enum class LabColor { Red, Yellow, Green, Cyan, Blue, Purple, White };
glm::vec3 labColor(LabColor color);

} // namespace raylab
