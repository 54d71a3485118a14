#include "screenshot.h"

#include "io/settings_json.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace raylab::viewer {

namespace {

std::string sceneOf(const ShownImage& shown) {
    return shown.scene ? shown.scene->source : std::string("cornell");
}

bool hasExtension(const std::string& path, const char* extension) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) {
        c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    }
    return ext == extension;
}

std::map<std::string, std::string> chunksFor(const ShownImage& shown) {
    return {{kSettingsChunk, settingsToJson(shown.settings, sceneOf(shown))},
            {kSceneChunk, sceneOf(shown)},
            {"Software", "raylab"}};
}

constexpr int kMaxNumber = 9999;

} // namespace

std::string settingsPathFor(const std::string& path) {
    return std::filesystem::path(path).replace_extension(".json").string();
}

bool saveScreenshot(const std::string& path, const ShownImage& shown, std::string& error) {
    if (hasExtension(path, ".png")) {
        if (!writePng(path, rgbaOf(shown), error, chunksFor(shown))) {
            return false;
        }
    } else if (shown.linear.pixels.empty()) {
        error = path + ": no linear picture to write (only .png is available)";
        return false;
    } else if (!writeImage(path, shown.linear, shown.settings.display, shown.settings.exposure,
                           error)) {
        return false;
    }
    if (!saveSettingsFile(settingsPathFor(path), shown.settings, sceneOf(shown), error)) {
        std::remove(path.c_str());
        return false;
    }
    return true;
}

bool saveNumberedScreenshot(const std::string& dir, const ShownImage& shown, std::string& path,
                            std::string& error) {
    namespace fs = std::filesystem;
    const fs::path folder = dir.empty() ? fs::path(".") : fs::path(dir);
    // Written under a private name first; link(2) then gives it its final name only if that
    // name is free, atomically.
    const fs::path temporary =
        folder / (".raylab-screenshot-" + std::to_string(::getpid()) + ".png.tmp");
    if (!writePng(temporary.string(), rgbaOf(shown), error, chunksFor(shown))) {
        return false;
    }
    bool claimed = false;
    for (int n = 1; n <= kMaxNumber && !claimed; ++n) {
        char name[32];
        std::snprintf(name, sizeof name, "raylab-%04d", n);
        const fs::path png = folder / (std::string(name) + ".png");
        const fs::path json = folder / (std::string(name) + ".json");
        std::error_code ignored;
        if (fs::exists(json, ignored)) {
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
    if (!saveSettingsFile(settingsPathFor(path), shown.settings, sceneOf(shown), error)) {
        std::remove(path.c_str());
        return false;
    }
    return true;
}

} // namespace raylab::viewer
