#include "input_checks.h"

#include "core/render_settings.h"
#include "io/command_line.h"
#include "io/image_io.h"
#include "io/partial_file.h"
#include "io/screenshot_settings.h"
#include "io/session_recording.h"
#include "io/settings_json.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>
#include <vector>

namespace raylab::fuzz {
namespace {

// The input written to a file of this process's own (the readers open files by name).
std::string asFile(const uint8_t* data, std::size_t size, const char* extension) {
    static const std::filesystem::path dir = [] {
        std::filesystem::path d = std::filesystem::temp_directory_path() /
                                  ("raylab-fuzz-inputs-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::string path = (dir / (std::string("input") + extension)).string();
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (file != nullptr) {
        if (size > 0) {
            std::fwrite(data, 1, size, file);
        }
        std::fclose(file);
    }
    return path;
}

std::string oneLine(const std::string& what, const std::string& error) {
    if (error.empty()) {
        return what + ": refused with no message";
    }
    if (error.find('\n') != std::string::npos) {
        return what + ": refused with more than one line: " + error;
    }
    return {};
}

} // namespace

std::string checkPartialFile(const uint8_t* data, std::size_t size) {
    PartialRender partial;
    std::string error;
    if (!readPartial(asFile(data, size, ".exr"), partial, error)) {
        return oneLine("partial file", error);
    }
    const FilmWindow& w = partial.window;
    if (w.x0 < 0 || w.y0 < 0 || w.x1 > partial.imageWidth || w.y1 > partial.imageHeight ||
        w.width() < 1 || w.height() < 1 || partial.firstSample >= partial.endSample ||
        partial.sums.size() != static_cast<std::size_t>(w.width()) * w.height() ||
        (!partial.squares.empty() && partial.squares.size() != partial.sums.size())) {
        return "partial file: accepted with a window, range or pixel count that do not agree";
    }
    return {};
}

std::string checkRecording(const std::string& text) {
    SessionRecording recording;
    std::string error;
    if (!recordingFromJson(text, recording, error)) {
        return oneLine("recording", error);
    }
    for (const RecordedEvent& event : recording.events) {
        if (event.state) {
            if (const std::string why = validate(event.state->settings); !why.empty()) {
                return "recording: accepted settings validate() refuses: " + why;
            }
        }
    }
    SessionRecording back;
    if (!recordingFromJson(recordingToJson(recording), back, error)) {
        return "recording: what was written does not read back: " + error;
    }
    if (!(back == recording)) {
        return "recording: a write and read back changed it";
    }
    return {};
}

std::string checkSettingsJson(const uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (const std::string why = checkRecording(text); !why.empty()) {
        return why;
    }
    RenderSettings settings;
    SettingsJsonExtras extras;
    std::string error;
    if (!settingsFromJson(text, settings, extras, error)) {
        return oneLine("settings", error);
    }
    if (const std::string why = validate(settings); !why.empty()) {
        return "settings: accepted values validate() refuses: " + why;
    }
    SettingsFileExtras fileExtras;
    fileExtras.split = extras.split;
    fileExtras.bookmarks = extras.bookmarks;
    fileExtras.frames = extras.frames;
    const std::string written = settingsToJson(settings, extras.scene, fileExtras);
    RenderSettings back;
    SettingsJsonExtras backExtras;
    if (!settingsFromJson(written, back, backExtras, error)) {
        return "settings: what was written does not read back: " + error;
    }
    if (!(back == settings) || !(backExtras.bookmarks == extras.bookmarks) ||
        backExtras.frames != extras.frames || backExtras.scene != extras.scene) {
        return "settings: a write and read back changed them";
    }
    return {};
}

std::string checkCommandLine(const uint8_t* data, std::size_t size) {
    if (size == 0) {
        return {};
    }
    const Program program = data[0] % 3 == 0   ? Program::Render
                            : data[0] % 3 == 1 ? Program::Viewer
                                               : Program::Bench;
    std::vector<std::string> words{"raylab"};
    std::string word;
    for (std::size_t i = 1; i < size; ++i) {
        if (data[i] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word += static_cast<char>(data[i]);
        }
    }
    words.push_back(word);
    std::vector<const char*> argv;
    for (const std::string& w : words) {
        argv.push_back(w.c_str());
    }
    CommandLine commandLine;
    std::string error;
    const int code =
        parseCommandLine(static_cast<int>(argv.size()), argv.data(), program, commandLine, error);
    if (code == 0) {
        if (commandLine.help) {
            return {};
        }
        if (const std::string why = validate(commandLine.settings); !why.empty()) {
            return "command line: accepted settings validate() refuses: " + why;
        }
        return {};
    }
    if (code != 1 && code != 2) {
        return "command line: exit code " + std::to_string(code);
    }
    return oneLine("command line", error);
}

std::string checkLinearImage(const uint8_t* data, std::size_t size) {
    if (size == 0) {
        return {};
    }
    const bool exr = (data[0] & 1) != 0;
    const std::string path = asFile(data + 1, size - 1, exr ? ".exr" : ".pfm");
    Framebuffer image;
    std::string error;
    const bool read = exr ? readExr(path, image, error) : readPfm(path, image, error);
    if (!read) {
        return oneLine(exr ? "exr" : "pfm", error);
    }
    if (image.width < 1 || image.height < 1 || image.width > kMaxImageSide ||
        image.height > kMaxImageSide ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height) {
        return "image: accepted with a size that does not agree with its pixels";
    }
    return {};
}

std::string checkScreenshotPng(const uint8_t* data, std::size_t size) {
    RenderSettings settings;
    SettingsJsonExtras extras;
    std::string error;
    if (!readScreenshotSettings(asFile(data, size, ".png"), settings, extras, error)) {
        return oneLine("screenshot", error);
    }
    if (const std::string why = validate(settings); !why.empty()) {
        return "screenshot: accepted values validate() refuses: " + why;
    }
    return {};
}

} // namespace raylab::fuzz
