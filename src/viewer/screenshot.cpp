#include "screenshot.h"

#include "core/cornell_box.h"
#include "io/settings_json.h"
#include "io/text_util.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace raylab::viewer {

namespace {

std::string sceneOf(const ShownImage& shown) {
    return shown.scene ? shown.scene->source : std::string(kLabBoxName);
}

// `path` with "-right" before its extension and .json after (a.png -> a-right.json).
std::string rightSettingsPathFor(const std::string& path) {
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + "-right.json")).string();
}

// The split records of a split picture whose image is at `path`: the left side's settings go to
// the image's own .json (and its PNG chunk), the right side's to a -right.json beside it.
// A difference picture's records carry its scale.
float differenceOf(const ShownImage& shown) {
    return shown.compareMode == CompareMode::Difference ? shown.differenceScale : 0.0f;
}
SplitRecord leftRecord(const ShownImage& shown, const std::string& path) {
    return {shown.divider, "left", std::filesystem::path(rightSettingsPathFor(path)).filename(),
            differenceOf(shown)};
}
SplitRecord rightRecord(const ShownImage& shown, const std::string& path) {
    return {shown.divider, "right", std::filesystem::path(settingsPathFor(path)).filename(),
            differenceOf(shown)};
}

// The extras of the left (or only) side's settings: the split record when the picture is split
// (`path` empty: the image's name is not known yet, and the record names no other file), the
// bookmarks and the observer view's lab camera.
SettingsFileExtras leftExtras(const ShownImage& shown, const std::string& path,
                              const ScreenshotExtras& viewer) {
    SettingsFileExtras extras;
    extras.bookmarks = viewer.bookmarks;
    extras.observedLabCamera = viewer.observedLabCamera;
    if (shown.compare) {
        extras.split = leftRecord(shown, path.empty() ? "x.png" : path);
        if (path.empty()) {
            extras.split->other.clear();
        }
    }
    return extras;
}

std::map<std::string, std::string> chunksFor(const ShownImage& shown, const std::string& path,
                                             const ScreenshotExtras& viewer) {
    return {{kSettingsChunk,
             settingsToJson(shown.settings, sceneOf(shown), leftExtras(shown, path, viewer))},
            {kSceneChunk, sceneOf(shown)},
            {"Software", "raylab"}};
}

// The settings beside the image at `path`: its .json, and for a split picture the right side's
// -right.json too. On failure removes what it wrote.
bool saveSettingsFor(const std::string& path, const ShownImage& shown,
                     const ScreenshotExtras& viewer, std::string& error) {
    const std::string json = settingsPathFor(path);
    if (!saveSettingsFile(json, shown.settings, sceneOf(shown), leftExtras(shown, path, viewer),
                          error)) {
        return false;
    }
    if (!shown.compare) {
        return true;
    }
    SettingsFileExtras right;
    right.split = rightRecord(shown, path);
    right.bookmarks = viewer.bookmarks;
    right.observedLabCamera = viewer.observedLabCamera;
    if (!saveSettingsFile(rightSettingsPathFor(path), *shown.compare, sceneOf(shown), right,
                          error)) {
        std::remove(json.c_str());
        return false;
    }
    return true;
}

constexpr int kMaxNumber = 9999;

} // namespace

std::string settingsPathFor(const std::string& path) {
    return std::filesystem::path(path).replace_extension(".json").string();
}

bool saveScreenshot(const std::string& path, const ShownImage& shown, std::string& error,
                    const ScreenshotExtras& viewer) {
    if (extensionOf(path) == ".png") {
        if (!writePng(path, rgbaOf(shown), error, chunksFor(shown, path, viewer))) {
            return false;
        }
    } else if (shown.linear.pixels.empty()) {
        error = path + ": no linear picture to write (only .png is available)";
        return false;
    } else if (!writeImage(path, shown.linear, shown.settings.display, shown.settings.exposure,
                           error)) {
        return false;
    }
    if (!saveSettingsFor(path, shown, viewer, error)) {
        std::remove(path.c_str());
        return false;
    }
    return true;
}

bool saveNumberedScreenshot(const std::string& dir, const ShownImage& shown, std::string& path,
                            std::string& error, const ScreenshotExtras& viewer) {
    namespace fs = std::filesystem;
    const fs::path folder = dir.empty() ? fs::path(".") : fs::path(dir);
    // Written under a private name first; link(2) then gives it its final name only if that
    // name is free, atomically.
    const fs::path temporary =
        folder / (".raylab-screenshot-" + std::to_string(::getpid()) + ".png.tmp");
    // The PNG's own name is not known yet: its chunk's split record names no other file.
    if (!writePng(temporary.string(), rgbaOf(shown), error, chunksFor(shown, "", viewer))) {
        return false;
    }
    bool claimed = false;
    for (int n = 1; n <= kMaxNumber && !claimed; ++n) {
        char name[32];
        std::snprintf(name, sizeof name, "raylab-%04d", n);
        const fs::path png = folder / (std::string(name) + ".png");
        const fs::path json = folder / (std::string(name) + ".json");
        std::error_code ignored;
        if (fs::exists(json, ignored) ||
            fs::exists(folder / (std::string(name) + ".exr"), ignored) ||
            (shown.compare && fs::exists(rightSettingsPathFor(png.string()), ignored))) {
            continue;
        }
        if (::link(temporary.c_str(), png.c_str()) == 0) {
            claimed = true;
            path = png.string();
        } else if (errno != EEXIST) {
            error = png.string() + ": " + std::strerror(errno);
            break;
        }
    }
    std::remove(temporary.c_str());
    if (!claimed) {
        if (error.empty()) {
            error = folder.string() + ": no free screenshot name up to raylab-9999.png";
        }
        return false;
    }
    if (!saveSettingsFor(path, shown, viewer, error)) {
        std::remove(path.c_str());
        return false;
    }
    // The linear picture beside it, when the picture came with one.
    if (!shown.linear.pixels.empty()) {
        const std::string exr = std::filesystem::path(path).replace_extension(".exr").string();
        if (!writeExr(exr, shown.linear, error)) {
            std::remove(path.c_str());
            std::remove(settingsPathFor(path).c_str());
            std::remove(rightSettingsPathFor(path).c_str());
            return false;
        }
    }
    return true;
}

} // namespace raylab::viewer
