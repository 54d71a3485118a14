#pragma once
// Reading back what a raylab screenshot was taken with, for a screenshot dropped on the viewer:
// the settings (and the scene) as JSON, in a .json beside the picture or in the PNG's own
// "raylab-settings" text chunk. The viewer writes both (viewer/screenshot.h).

#include "core/render_settings.h"
#include "io/settings_json.h"

#include <string>

namespace raylab {

inline constexpr const char* kSettingsChunk = "raylab-settings";
inline constexpr const char* kSceneChunk = "raylab-scene";

// Whether a path names a screenshot's settings (.png or .json, in any case) rather than a mesh.
bool isScreenshotPath(const std::string& path);

// Reads the settings a raylab screenshot was taken with: a .json file, or a .png's
// "raylab-settings" chunk, over `settings` (its scene and bookmarks into `extras`). False with a
// one-line error naming the file for anything else (a PNG without the chunk is not a raylab
// screenshot).
bool readScreenshotSettings(const std::string& path, RenderSettings& settings,
                            SettingsJsonExtras& extras, std::string& error);

} // namespace raylab
