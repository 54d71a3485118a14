#pragma once
// Screenshots: the rendered picture at render resolution (no panel) as PNG, with the exact
// settings that reproduce it twice: as JSON (with its "scene") in the PNG's "raylab-settings"
// tEXt chunk and as a .json file beside it, so that
//   raylab-render --settings that.json -o again.png
// writes the same bytes. A split picture (ShownImage::compare) records both sides: the image's
// .json holds the left side's settings and a "split" record, a -right.json beside it the right
// side's, so that raylab-render reproduces each side from its file.
// A screenshot of the difference (ShownImage::compareMode) is what the window shows: the PNG
// holds the colour scale of left - right, the linear picture (.exr, .pfm) the signed difference
// per channel, and both sides' files record "difference": the scale. raylab-render reproduces
// it from the two sides' files: render each as PFM, subtract, and map with
// differenceColour (difference_view.h).
// A screenshot in the observer view is the observer's picture: its settings' "camera" is the
// observer's (raylab-render reproduces the picture from it), and its "observer" record keeps the
// lab camera (ScreenshotExtras::observedLabCamera).

#include "io/screenshot_settings.h"
#include "io/settings_json.h"
#include "shown_image.h"

#include <optional>
#include <string>

namespace raylab::viewer {

// What the viewer keeps in a screenshot's settings files besides the picture's settings: its camera
// bookmarks and, in the observer view (observer_view.h), the lab camera kept while the picture is
// the observer's (SettingsFileExtras::observedLabCamera).
struct ScreenshotExtras {
    CameraBookmarks bookmarks;
    std::optional<Camera> observedLabCamera;
};

// `path` with its extension replaced by .json (a.png -> a.json).
std::string settingsPathFor(const std::string& path);

// Writes the picture at `path` and its settings beside it: a .png gets the displayed bytes and the
// text chunks; .pfm and .exr get ShownImage::linear (which must be there), each atomically
// (temporary file and rename; a failure leaves no file). Overwrites existing files: the caller
// chose the name.
// `viewer`: what the viewer keeps in the settings files besides the settings.
bool saveScreenshot(const std::string& path, const ShownImage& shown, std::string& error,
                    const ScreenshotExtras& viewer = {});

// Writes into `dir` under the first name raylab-0001.png, raylab-0002.png, ... whose .png, .json
// (and .exr) are free, with the linear picture as raylab-NNNN.exr when ShownImage::linear holds
// it, never overwriting a file, even one another process creates meanwhile
// (the name is claimed with link(2)). Sets `path` to the PNG written.
bool saveNumberedScreenshot(const std::string& dir, const ShownImage& shown, std::string& path,
                            std::string& error, const ScreenshotExtras& viewer = {});

} // namespace raylab::viewer
