#pragma once
// RenderSettings as JSON. Every field is optional when reading: missing ones keep the value they
// had. Unknown keys, wrong types and invalid values are errors.
//
// The format (units: world units, degrees, watts, stops):
//   {"camera":   {"position": [0, 0, -3], "yaw": 0, "pitch": 0, "fov": 53.130104},
//    "light":    {"position": [0, 0.5, -0.7], "color": [1, 1, 1], "intensity": 14},
//    "indirect": {"enabled": true, "color": [1, 1, 1], "intensity": 0.5},
//    "shadows":  {"enabled": true, "epsilon": 0.001},
//    "image":    {"width": 500, "height": 500, "samples": 1},
//    "threads":  0,
//    "display":  {"mode": "lab", "exposure": 0},
//    "scene":    "cornell",                       <- optional; only written when asked for
//    "split":    {"divider": 0.5, "side": "left", "other": "raylab-0001-right.json",
//                 "difference": 0.1},
//    "bookmarks": [null, {"position": [0, 0, -3], "yaw": 0, "pitch": 0, "fov": 53.13}, ...]}
//                 <- optional: a screenshot of one side of the viewer's A/B split; these are that
//                    side's settings, `other` names the file of the other side's, `difference`
//                    (optional) the scale of a difference picture (SplitRecord);
//                 "bookmarks": the viewer's camera bookmarks, 9 slots (optional)
// (also "integrator", "emission", a light's "radius" and the display's "view": see toJson).
// Floats are written in the shortest form that reads back to the same float, so a save and a load
// reproduce the settings bit for bit.

#include "core/render_settings.h"

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace raylab {

std::string settingsToJson(const RenderSettings& settings);
// The same plus a top-level "scene" (the built-in scene's name or the mesh path), for screenshots
// and --save-settings.
std::string settingsToJson(const RenderSettings& settings, const std::string& scene);

// Which side of a split picture a settings file describes.
struct SplitRecord {
    float divider = 0.5f; // the fraction of the width the left side showed
    // "left" or "right"; left where a file's record names no side
    std::string side = "left";
    std::string other; // the file of the other side's settings (a name beside this one);
                       // empty (not written) where it is not known, as in a PNG's chunk
    // > 0: the picture was not a wipe but the signed difference left - right, shown with this
    // value (W/m^2) in full colour (the viewer's difference_view.h), written "difference": scale;
    // 0: a wipe (not written).
    float difference = 0.0f;
    bool operator==(const SplitRecord&) const = default;
};

// The viewer's camera bookmarks (Ctrl+1..9 stores, 1..9 returns), kept in settings files as
// "bookmarks": an array of 9, each null or {"position", "yaw", "pitch", "fov"}.
struct CameraBookmarks {
    std::array<std::optional<Camera>, 9> slots;
    bool any() const;
    bool operator==(const CameraBookmarks&) const = default;
};

// What a settings file holds besides the settings: a split record, bookmarks, frames.
struct SettingsFileExtras {
    std::optional<SplitRecord> split;
    CameraBookmarks bookmarks; // written only when some slot is set
    // "frames": the cameras of an animation (e.g. raylab-render --turntable), one per frame,
    // each {"position", "yaw", "pitch", "fov"}; written only when not empty
    std::vector<Camera> frames;
    // "observer": {"lab_camera": camera}: the picture is the viewer's observer view (its "camera"
    // is the observer's), and this is the lab's camera, kept while the observer moved; written
    // only when set
    std::optional<Camera> observedLabCamera;
};

// The most frames a settings file may list.
inline constexpr std::size_t kMaxFrames = 100000;

// What a JSON text held besides the values.
struct SettingsJsonExtras {
    std::set<std::string> keys;       // the leaf keys it gave, e.g. "camera.position", "threads"
    std::string scene;                // its "scene", or empty
    std::optional<SplitRecord> split; // its "split", if any
    CameraBookmarks bookmarks;        // its "bookmarks", if any
    std::vector<Camera> frames;       // its "frames", if any
    std::optional<Camera> observedLabCamera; // its "observer"'s "lab_camera", if any
};

// Reads JSON text over settings. Returns false with a one-line error naming the key, leaving
// settings unchanged. Each value is checked with core validate() as it is applied.
bool settingsFromJson(const std::string& text, RenderSettings& settings, std::string& error);
bool settingsFromJson(const std::string& text, RenderSettings& settings, SettingsJsonExtras& extras,
                      std::string& error);

// Errors start with the path ("view.json: camera.fov: must be a number, got \"wide\"").
bool loadSettingsFile(const std::string& path, RenderSettings& settings, std::string& error);
bool loadSettingsFile(const std::string& path, RenderSettings& settings, SettingsJsonExtras& extras,
                      std::string& error);
// Atomic (temporary file and rename). An empty scene writes no "scene" key.
bool saveSettingsFile(const std::string& path, const RenderSettings& settings, std::string& error);
bool saveSettingsFile(const std::string& path, const RenderSettings& settings,
                      const std::string& scene, std::string& error);
// The same with a file's extras (an empty scene writes no "scene" key).
std::string settingsToJson(const RenderSettings& settings, const std::string& scene,
                           const SettingsFileExtras& extras);
bool saveSettingsFile(const std::string& path, const RenderSettings& settings,
                      const std::string& scene, const SettingsFileExtras& extras,
                      std::string& error);

} // namespace raylab
