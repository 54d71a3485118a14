#pragma once
// Rules for editing settings from the panel: widgets edit a copy, and the copy replaces the
// current settings only when it passes core's validate(), so a NaN, a negative power or a field of
// view outside (0, 180) is refused instead of drawn.

#include "core/render_settings.h"
#include "core/scene.h"

#include <string>

namespace raylab::viewer {

// Replaces `current` by `edited` when edited is valid and returns true; otherwise leaves current
// as it is, sets `why` to validate()'s one line and returns false.
bool acceptEdit(const RenderSettings& edited, RenderSettings& current, std::string& why);

// The shadow-epsilon slider: position t in [0, 1] on a logarithmic scale over kEpsilonDecades
// decades up to `maxEpsilon`, with t = 0 (the leftmost position) exactly epsilon 0.
inline constexpr float kEpsilonDecades = 6.0f;
float epsilonFromSlider(float t, float maxEpsilon);
float sliderFromEpsilon(float epsilon, float maxEpsilon);

// "Reset to the lab's defaults": the lab's camera, light, indirect term, shadows and display; the
// render size, sample cap and thread count are kept. A mesh scene is then framed (the lab's camera
// would not see it).
void resetToLabDefaults(const Scene& scene, bool isLabBox, RenderSettings& settings);

// The camera, light and shadow epsilon a newly opened scene starts with: the lab's for the lab's
// box, the framing of core/scene_framing.h for a mesh. Other settings are kept.
void placeForScene(const Scene& scene, bool isLabBox, RenderSettings& settings);

} // namespace raylab::viewer
