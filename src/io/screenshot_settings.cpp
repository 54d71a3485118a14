#include "io/screenshot_settings.h"

#include "io/image_io.h"
#include "io/text_util.h"

#include <map>

namespace raylab {

bool isScreenshotPath(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == ".png" || ext == ".json";
}

bool readScreenshotSettings(const std::string& path, RenderSettings& settings,
                            SettingsJsonExtras& extras, std::string& error) {
    if (extensionOf(path) == ".json") {
        return loadSettingsFile(path, settings, extras, error);
    }
    Rgba8Image image;
    std::map<std::string, std::string> chunks;
    if (!readPng(path, image, error, &chunks)) {
        return false;
    }
    const auto chunk = chunks.find(kSettingsChunk);
    if (chunk == chunks.end()) {
        error = path + ": not a raylab screenshot (no " + kSettingsChunk + " chunk)";
        return false;
    }
    if (!settingsFromJson(chunk->second, settings, extras, error)) {
        error = path + ": " + singleLine(error);
        return false;
    }
    return true;
}

} // namespace raylab
