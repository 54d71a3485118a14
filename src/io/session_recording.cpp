#include "io/session_recording.h"

#include "io/atomic_file.h"
#include "io/file_checks.h"
#include "io/text_util.h"

#include <cerrno>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

namespace raylab {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr int kFormatVersion = 1;
// A recording holds a settings object per change: a long session's is tens of megabytes.
constexpr std::uintmax_t kMaxRecordingBytes = 1u << 30;

OrderedJson parsedOrdered(const std::string& text) { return OrderedJson::parse(text); }

OrderedJson stateJson(const RecordedState& state) {
    SettingsFileExtras extras;
    extras.bookmarks = state.bookmarks;
    extras.observedLabCamera = state.labCamera;
    OrderedJson j;
    j["settings"] = parsedOrdered(settingsToJson(state.settings, state.scene, extras));
    if (state.compare) {
        j["compare"] = parsedOrdered(settingsToJson(*state.compare));
        j["split"] = {{"divider", state.divider},
                      {"mode", state.difference ? "difference" : "wipe"},
                      {"difference_scale", state.differenceScale}};
    }
    if (state.inspected) {
        RenderSettings picture = state.settings;
        picture.camera = state.inspected->camera;
        picture.width = state.inspected->width;
        picture.height = state.inspected->height;
        const OrderedJson whole = parsedOrdered(settingsToJson(picture));
        j["inspected"] = {
            {"pixel", {state.inspected->x, state.inspected->y}},
            {"picture",
             {{"camera", whole.at("camera")},
              {"image",
               {{"width", state.inspected->width}, {"height", state.inspected->height}}}}}};
    }
    return j;
}

// Reads one event's parts; errors name the key within the event.
class EventReader {
public:
    explicit EventReader(std::string& error) : error_(error) {}

    bool state(const Json& j, RecordedState& out) {
        if (!j.is_object()) {
            return fail("state", "must be an object");
        }
        for (const auto& [key, value] : j.items()) {
            if (key != "settings" && key != "compare" && key != "split" && key != "inspected") {
                return fail("state." + key, "unknown key");
            }
        }
        if (!j.contains("settings")) {
            return fail("state.settings", "missing");
        }
        SettingsJsonExtras extras;
        if (!settings(j.at("settings"), "state.settings", out.settings, &extras)) {
            return false;
        }
        if (extras.scene.empty()) {
            return fail("state.settings.scene", "missing");
        }
        if (extras.split || !extras.frames.empty()) {
            return fail("state.settings", "a recording's settings hold no split or frames");
        }
        out.scene = extras.scene;
        out.bookmarks = extras.bookmarks;
        out.labCamera = extras.observedLabCamera;
        if (j.contains("compare") != j.contains("split")) {
            return fail("state", "\"compare\" and \"split\" come together");
        }
        if (j.contains("compare")) {
            RenderSettings compare;
            if (!settings(j.at("compare"), "state.compare", compare, nullptr) ||
                !split(j.at("split"), out)) {
                return false;
            }
            if (compare.width != out.settings.width || compare.height != out.settings.height) {
                return fail("state.compare.image", "must have the settings' width and height");
            }
            out.compare = compare;
        }
        if (j.contains("inspected")) {
            return inspected(j.at("inspected"), out);
        }
        return true;
    }

    bool screenshot(const Json& j, bool split, RecordedScreenshot& out) {
        if (!j.is_object()) {
            return fail("screenshot", "must be an object");
        }
        for (const auto& [key, value] : j.items()) {
            if (key != "samples" && key != "compare_samples") {
                return fail("screenshot." + key, "unknown key");
            }
        }
        if (!count(j, "samples", "screenshot.samples", out.samples)) {
            return false;
        }
        if (split != j.contains("compare_samples")) {
            return fail("screenshot.compare_samples",
                        split ? "missing for a split picture" : "only for a split picture");
        }
        return !split ||
               count(j, "compare_samples", "screenshot.compare_samples", out.compareSamples);
    }

private:
    bool fail(const std::string& key, const std::string& why) {
        error_ = key + ": " + why;
        return false;
    }

    bool settings(const Json& j, const std::string& key, RenderSettings& out,
                  SettingsJsonExtras* extras) {
        if (!j.is_object()) {
            return fail(key, "must be an object");
        }
        SettingsJsonExtras ignored;
        std::string why;
        if (!settingsFromJson(j.dump(), out, extras ? *extras : ignored, why)) {
            return fail(key, why);
        }
        return true;
    }

    // A positive whole number of samples within RenderSettings' range.
    bool count(const Json& j, const char* name, const std::string& key, int& out) {
        if (!j.contains(name) || !j.at(name).is_number_integer()) {
            return fail(key, "must be a whole number");
        }
        const long long value = j.at(name).get<long long>();
        if (value < 1 || value > std::numeric_limits<int>::max()) {
            return fail(key, "must be at least 1, got " + std::to_string(value));
        }
        out = static_cast<int>(value);
        return true;
    }

    bool split(const Json& j, RecordedState& out) {
        if (!j.is_object()) {
            return fail("state.split", "must be an object");
        }
        for (const auto& [key, value] : j.items()) {
            if (key != "divider" && key != "mode" && key != "difference_scale") {
                return fail("state.split." + key, "unknown key");
            }
        }
        const auto number = [&](const char* name, float lowest, bool lowestIncluded, float highest,
                                float& value) {
            if (!j.contains(name) || !j.at(name).is_number()) {
                return fail(std::string("state.split.") + name, "must be a number");
            }
            const double v = j.at(name).get<double>();
            if (!(lowestIncluded ? v >= lowest : v > lowest) || !(v <= highest)) {
                return fail(std::string("state.split.") + name, "out of range");
            }
            value = static_cast<float>(v);
            return true;
        };
        if (!number("divider", 0.0f, true, 1.0f, out.divider) ||
            !number("difference_scale", 0.0f, false, std::numeric_limits<float>::max(),
                    out.differenceScale)) {
            return false;
        }
        if (!j.contains("mode") || !j.at("mode").is_string() ||
            (j.at("mode") != "wipe" && j.at("mode") != "difference")) {
            return fail("state.split.mode", "must be \"wipe\" or \"difference\"");
        }
        out.difference = j.at("mode") == "difference";
        return true;
    }

    bool inspected(const Json& j, RecordedState& out) {
        if (!j.is_object() || !j.contains("pixel") || !j.contains("picture")) {
            return fail("state.inspected", "must be {\"pixel\": [x, y], \"picture\": {...}}");
        }
        for (const auto& [key, value] : j.items()) {
            if (key != "pixel" && key != "picture") {
                return fail("state.inspected." + key, "unknown key");
            }
        }
        RenderSettings picture = out.settings;
        if (!settings(j.at("picture"), "state.inspected.picture", picture, nullptr)) {
            return false;
        }
        const Json& pixel = j.at("pixel");
        if (!pixel.is_array() || pixel.size() != 2 || !pixel[0].is_number_integer() ||
            !pixel[1].is_number_integer()) {
            return fail("state.inspected.pixel", "must be [x, y], whole numbers");
        }
        const long long x = pixel[0].get<long long>(), y = pixel[1].get<long long>();
        if (x < 0 || y < 0 || x >= picture.width || y >= picture.height) {
            return fail("state.inspected.pixel", "outside the picture it was picked in");
        }
        out.inspected = RecordedInspection{static_cast<int>(x), static_cast<int>(y), picture.camera,
                                           picture.width, picture.height};
        return true;
    }

    std::string& error_;
};

bool readRecording(const Json& root, SessionRecording& out, std::string& error) {
    if (!root.is_object()) {
        error = "a recording must be a JSON object";
        return false;
    }
    for (const auto& [key, value] : root.items()) {
        if (key != "raylab_recording" && key != "frames" && key != "events") {
            error = key + ": unknown key";
            return false;
        }
    }
    if (!root.contains("raylab_recording") || root.at("raylab_recording") != kFormatVersion) {
        error = "not a raylab recording of version " + std::to_string(kFormatVersion) +
                " (\"raylab_recording\": " + std::to_string(kFormatVersion) + ")";
        return false;
    }
    if (!root.contains("frames") || !root.at("frames").is_number_integer() ||
        root.at("frames").get<long long>() < 0 ||
        root.at("frames").get<long long>() > std::numeric_limits<long>::max()) {
        error = "frames: must be a whole number, at least 0";
        return false;
    }
    out.frames = root.at("frames").get<long>();
    if (!root.contains("events") || !root.at("events").is_array() || root.at("events").empty()) {
        error = "events: must be a list that starts with a state";
        return false;
    }
    const Json& events = root.at("events");
    if (events.size() > kMaxRecordedEvents) {
        error = "events: more than " + std::to_string(kMaxRecordedEvents);
        return false;
    }
    out.events.clear();
    out.events.reserve(events.size());
    bool split = false; // the state in force is a split picture
    long previousFrame = 0;
    EventReader reader(error);
    for (std::size_t i = 0; i < events.size(); ++i) {
        const Json& e = events[i];
        const std::string where = "events[" + std::to_string(i) + "]";
        RecordedEvent event;
        bool ok = e.is_object() && e.contains("frame") && e.at("frame").is_number_integer() &&
                  e.size() == 2 && (e.contains("state") != e.contains("screenshot"));
        if (!ok) {
            error = where + ": must be {\"frame\": N, \"state\": {...}} or {\"frame\": N, "
                            "\"screenshot\": {...}}";
            return false;
        }
        const long long frame = e.at("frame").get<long long>();
        if (frame < previousFrame || frame > out.frames) {
            error = where + ".frame: " + std::to_string(frame) + " is not within [" +
                    std::to_string(previousFrame) + ", " + std::to_string(out.frames) + "]";
            return false;
        }
        event.frame = static_cast<long>(frame);
        previousFrame = event.frame;
        if (e.contains("state")) {
            RecordedState state;
            ok = reader.state(e.at("state"), state);
            split = state.compare.has_value();
            event.state = std::move(state);
        } else if (i == 0) {
            error = where + ": the first event must be a state";
            return false;
        } else {
            RecordedScreenshot shot;
            ok = reader.screenshot(e.at("screenshot"), split, shot);
            event.screenshot = shot;
        }
        if (!ok) {
            error = where + "." + error;
            return false;
        }
        out.events.push_back(std::move(event));
    }
    return true;
}

} // namespace

std::string recordingToJson(const SessionRecording& recording) {
    // One event a line: a recording stays readable and diffable.
    std::string text = "{\"raylab_recording\": " + std::to_string(kFormatVersion) +
                       ", \"frames\": " + std::to_string(recording.frames) + ",\n \"events\": [";
    for (std::size_t i = 0; i < recording.events.size(); ++i) {
        const RecordedEvent& event = recording.events[i];
        OrderedJson j;
        j["frame"] = event.frame;
        if (event.state) {
            j["state"] = stateJson(*event.state);
        } else if (event.screenshot) {
            j["screenshot"] = {{"samples", event.screenshot->samples}};
            if (event.screenshot->compareSamples > 0) {
                j["screenshot"]["compare_samples"] = event.screenshot->compareSamples;
            }
        }
        text += i == 0 ? "\n  " : ",\n  ";
        text += j.dump();
    }
    text += "]}\n";
    return text;
}

bool recordingFromJson(const std::string& text, SessionRecording& recording, std::string& error) {
    const SingleLineOnExit oneLine(error);
    Json root;
    try {
        root = Json::parse(text);
    } catch (const Json::exception& e) {
        error = jsonParseError(e.what());
        return false;
    }
    SessionRecording read;
    if (!readRecording(root, read, error)) {
        return false;
    }
    recording = std::move(read);
    return true;
}

bool loadRecording(const std::string& path, SessionRecording& recording, std::string& error) {
    std::string text;
    if (!readRegularTextFile(path, "recording", kMaxRecordingBytes, text, error)) {
        return false;
    }
    if (!recordingFromJson(text, recording, error)) {
        error = path + ": " + error;
        return false;
    }
    return true;
}

bool saveRecording(const std::string& path, const SessionRecording& recording, std::string& error) {
    const std::string text = recordingToJson(recording);
    return writeFileAtomically(
        path,
        [&](std::FILE* file, std::string& why) {
            if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) {
                why = std::strerror(errno);
                return false;
            }
            return true;
        },
        error);
}

} // namespace raylab
