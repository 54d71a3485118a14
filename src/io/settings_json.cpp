#include "io/settings_json.h"

#include "io/atomic_file.h"
#include "io/file_checks.h"
#include "io/text_util.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>

namespace raylab {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

// The double with the shortest decimal form that still converts back to f: 0.1f is written as
// 0.1, not 0.100000001490116. Falls back to the exact value if the short form does not round-trip.
double shortFloat(float f) {
    if (!std::isfinite(f)) {
        return static_cast<double>(f); // written as null; the reader then rejects it
    }
    char buffer[64];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, f);
    double d = 0.0;
    const auto parsed = std::from_chars(buffer, written.ptr, d);
    if (written.ec != std::errc() || parsed.ec != std::errc() || static_cast<float>(d) != f) {
        return static_cast<double>(f);
    }
    return d;
}

OrderedJson vec3Json(const glm::vec3& v) {
    return OrderedJson::array({shortFloat(v.x), shortFloat(v.y), shortFloat(v.z)});
}

OrderedJson toJson(const RenderSettings& s) {
    OrderedJson j;
    j["camera"] = {{"position", vec3Json(s.camera.position)},
                   {"yaw", shortFloat(s.camera.yawDegrees)},
                   {"pitch", shortFloat(s.camera.pitchDegrees)},
                   {"fov", shortFloat(s.camera.verticalFovDegrees)}};
    j["light"] = {{"position", vec3Json(s.light.position)},
                  {"color", vec3Json(s.light.color)},
                  {"intensity", shortFloat(s.light.intensity)},
                  {"radius", shortFloat(s.light.radius)}};
    j["indirect"] = {{"enabled", s.indirect},
                     {"color", vec3Json(s.indirectColor)},
                     {"intensity", shortFloat(s.indirectIntensity)}};
    j["shadows"] = {{"enabled", s.shadows}, {"epsilon", shortFloat(s.shadowEpsilon)}};
    j["image"] = {{"width", s.width}, {"height", s.height}, {"samples", s.samplesPerPixel}};
    j["threads"] = s.threads;
    j["display"] = {{"mode", toString(s.display)},
                    {"exposure", shortFloat(s.exposure)},
                    {"view", toString(s.view)}};
    j["integrator"] = {{"kind", toString(s.integrator)},
                       {"max_bounces", s.maxBounces},
                       {"sampler", toString(s.sampler)}};
    j["emission"] = {{"scale", shortFloat(s.emissionScale)}};
    return j;
}

// A JSON value for an error message, cut short.
std::string shown(const Json& value) {
    std::string text = value.dump();
    if (text.size() > 40) {
        text = text.substr(0, 37) + "...";
    }
    return text;
}

// Applies one JSON document to a copy of the settings, key by key, and names the first key that
// is unknown, of the wrong type, or makes validate() fail.
class Reader {
public:
    Reader(RenderSettings& settings, SettingsJsonExtras& extras, std::string& error)
        : work_(settings), extras_(extras), error_(error),
          startedValid_(validate(settings).empty()) {}

    bool read(const Json& root) {
        if (!root.is_object()) {
            return fail("", "the settings must be a JSON object, got " + shown(root));
        }
        for (const auto& [key, value] : root.items()) {
            bool ok = true;
            if (key == "camera") {
                ok = section(key, value,
                             {{"position", vec3(&work_.camera.position)},
                              {"yaw", number(&work_.camera.yawDegrees)},
                              {"pitch", number(&work_.camera.pitchDegrees)},
                              {"fov", number(&work_.camera.verticalFovDegrees)}});
            } else if (key == "light") {
                ok = section(key, value,
                             {{"position", vec3(&work_.light.position)},
                              {"color", vec3(&work_.light.color)},
                              {"intensity", number(&work_.light.intensity)},
                              {"radius", number(&work_.light.radius)}});
            } else if (key == "indirect") {
                ok = section(key, value,
                             {{"enabled", boolean(&work_.indirect)},
                              {"color", vec3(&work_.indirectColor)},
                              {"intensity", number(&work_.indirectIntensity)}});
            } else if (key == "shadows") {
                ok = section(key, value,
                             {{"enabled", boolean(&work_.shadows)},
                              {"epsilon", number(&work_.shadowEpsilon)}});
            } else if (key == "image") {
                ok = section(key, value,
                             {{"width", integer(&work_.width)},
                              {"height", integer(&work_.height)},
                              {"samples", integer(&work_.samplesPerPixel)}});
            } else if (key == "threads") {
                ok = leaf(key, value, integer(&work_.threads));
            } else if (key == "display") {
                ok = section(key, value,
                             {{"mode", displayMode(&work_.display)},
                              {"exposure", number(&work_.exposure)},
                              {"view", viewSetter(&work_.view)}});
            } else if (key == "integrator") {
                ok = section(key, value,
                             {{"kind", integrator(&work_.integrator)},
                              {"max_bounces", integer(&work_.maxBounces)},
                              {"sampler", samplerKind(&work_.sampler)}});
            } else if (key == "emission") {
                ok = section(key, value, {{"scale", number(&work_.emissionScale)}});
            } else if (key == "frames") {
                ok = readFrames(value);
            } else if (key == "observer") {
                if (!readObserver(value)) {
                    return false;
                }
            } else if (key == "bookmarks") {
                if (!readBookmarks(value)) {
                    return false;
                }
            } else if (key == "split") {
                if (!readSplit(value)) {
                    return false;
                }
            } else if (key == "scene") {
                if (!value.is_string() || value.get<std::string>().empty()) {
                    return fail(key, "must be a non-empty string, got " + shown(value));
                }
                extras_.scene = value.get<std::string>();
                extras_.keys.insert(key);
            } else {
                return fail(key, "unknown key");
            }
            if (!ok) {
                return false;
            }
        }
        return true;
    }

    const RenderSettings& result() const { return work_; }

    // One camera, {"position": [x, y, z], "yaw": deg, "pitch": deg, "fov": deg}, valid as a
    // camera of the settings is; keys left out keep the defaults.
    bool readCamera(const std::string& name, const Json& value, Camera& camera) {
        if (!value.is_object()) {
            return fail(name, "must be a camera, got " + shown(value));
        }
        RenderSettings probe;
        for (const auto& [key, child] : value.items()) {
            std::string why;
            if (key == "position") {
                why = vec3(&probe.camera.position)(child);
            } else if (key == "yaw") {
                why = asFloat(child, probe.camera.yawDegrees);
            } else if (key == "pitch") {
                why = asFloat(child, probe.camera.pitchDegrees);
            } else if (key == "fov") {
                why = asFloat(child, probe.camera.verticalFovDegrees);
            } else {
                why = "unknown key";
            }
            if (!why.empty()) {
                return fail(name + "." + key, why);
            }
        }
        if (std::string why = validate(probe); !why.empty()) {
            return fail(name, why);
        }
        camera = probe.camera;
        return true;
    }

    // "bookmarks": [9 x (null | camera)].
    bool readBookmarks(const Json& value) {
        if (!value.is_array() || value.size() != 9) {
            return fail("bookmarks", "must be an array of 9 cameras or nulls, got " + shown(value));
        }
        CameraBookmarks bookmarks;
        for (std::size_t i = 0; i < 9; ++i) {
            if (value[i].is_null()) {
                continue;
            }
            Camera camera;
            if (!readCamera("bookmarks[" + std::to_string(i) + "]", value[i], camera)) {
                return false;
            }
            bookmarks.slots[i] = camera;
        }
        extras_.bookmarks = bookmarks;
        extras_.keys.insert("bookmarks");
        return true;
    }

    // "observer": {"lab_camera": camera}.
    bool readObserver(const Json& value) {
        if (!value.is_object() || value.size() != 1 || !value.contains("lab_camera")) {
            return fail("observer", "must be {\"lab_camera\": camera}, got " + shown(value));
        }
        Camera camera;
        if (!readCamera("observer.lab_camera", value["lab_camera"], camera)) {
            return false;
        }
        extras_.observedLabCamera = camera;
        extras_.keys.insert("observer");
        return true;
    }

    // "frames": [camera, ...], 1 to kMaxFrames of them.
    bool readFrames(const Json& value) {
        if (!value.is_array() || value.empty() || value.size() > kMaxFrames) {
            return fail("frames", "must be an array of 1 to " + std::to_string(kMaxFrames) +
                                      " cameras, got " + shown(value));
        }
        std::vector<Camera> frames(value.size());
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!readCamera("frames[" + std::to_string(i) + "]", value[i], frames[i])) {
                return false;
            }
        }
        extras_.frames = std::move(frames);
        extras_.keys.insert("frames");
        return true;
    }

    // "split": {"divider": number in [0, 1], "side": "left" | "right", "other": file name,
    // "difference": number > 0}.
    bool readSplit(const Json& value) {
        if (!value.is_object()) {
            return fail("split", "must be an object, got " + shown(value));
        }
        SplitRecord split;
        for (const auto& [key, child] : value.items()) {
            if (key == "divider") {
                if (std::string why = asFloat(child, split.divider);
                    !why.empty() || split.divider < 0.0f || split.divider > 1.0f) {
                    return fail("split.divider", "must be a number in [0, 1], got " + shown(child));
                }
            } else if (key == "side") {
                if (!child.is_string() ||
                    (child.get<std::string>() != "left" && child.get<std::string>() != "right")) {
                    return fail("split.side", "must be \"left\" or \"right\", got " + shown(child));
                }
                split.side = child.get<std::string>();
            } else if (key == "other") {
                if (!child.is_string() || child.get<std::string>().empty()) {
                    return fail("split.other", "must be a file name, got " + shown(child));
                }
                split.other = child.get<std::string>();
            } else if (key == "difference") {
                if (std::string why = asFloat(child, split.difference);
                    !why.empty() || !(split.difference > 0.0f) || std::isinf(split.difference)) {
                    return fail("split.difference",
                                "must be a positive number, got " + shown(child));
                }
            } else {
                return fail("split." + key, "unknown key");
            }
        }
        extras_.split = split;
        extras_.keys.insert("split");
        return true;
    }

private:
    // Parses value into its field; returns an empty string or what is wrong with the value.
    using Setter = std::function<std::string(const Json& value)>;
    struct Field {
        const char* name;
        Setter set;
    };

    static std::string asFloat(const Json& value, float& out) {
        if (!value.is_number()) {
            return "must be a number, got " + shown(value);
        }
        const double d = value.get<double>();
        const auto f = static_cast<float>(d);
        if (!std::isfinite(d) || !std::isfinite(f)) {
            return "must be a finite number, got " + shown(value);
        }
        out = f;
        return {};
    }

    static Setter number(float* field) {
        return [field](const Json& value) { return asFloat(value, *field); };
    }

    static Setter vec3(glm::vec3* field) {
        return [field](const Json& value) -> std::string {
            if (!value.is_array() || value.size() != 3) {
                return "must be an array of 3 numbers, got " + shown(value);
            }
            glm::vec3 v;
            for (int i = 0; i < 3; ++i) {
                if (std::string why = asFloat(value[static_cast<std::size_t>(i)], v[i]);
                    !why.empty()) {
                    return "must be an array of 3 finite numbers, got " + shown(value);
                }
            }
            *field = v;
            return {};
        };
    }

    static Setter integer(int* field) {
        return [field](const Json& value) -> std::string {
            if (!value.is_number_integer()) {
                return "must be an integer, got " + shown(value);
            }
            if (value.is_number_unsigned()
                    ? value.get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int>::max())
                    : (value.get<int64_t>() < std::numeric_limits<int>::min() ||
                       value.get<int64_t>() > std::numeric_limits<int>::max())) {
                return "is out of range: " + shown(value);
            }
            *field = static_cast<int>(value.get<int64_t>());
            return {};
        };
    }

    static Setter boolean(bool* field) {
        return [field](const Json& value) -> std::string {
            if (!value.is_boolean()) {
                return "must be true or false, got " + shown(value);
            }
            *field = value.get<bool>();
            return {};
        };
    }

    static Setter displayMode(DisplayMode* field) {
        return [field](const Json& value) -> std::string {
            if (!value.is_string() || !parseDisplayMode(value.get<std::string>(), *field)) {
                return "must be \"lab\" or \"srgb\", got " + shown(value);
            }
            return {};
        };
    }

    static Setter viewSetter(View* field) {
        return [field](const Json& value) -> std::string {
            if (!value.is_string() || !parseView(value.get<std::string>(), *field)) {
                return "must be one of beauty, albedo, direct, indirect, visibility, normal, "
                       "depth, cost; got " +
                       shown(value);
            }
            return {};
        };
    }

    static Setter integrator(Integrator* field) {
        return [field](const Json& value) -> std::string {
            if (!value.is_string() || !parseIntegrator(value.get<std::string>(), *field)) {
                return "must be \"lab\" or \"path\", got " + shown(value);
            }
            return {};
        };
    }

    static Setter samplerKind(SamplerKind* field) {
        return [field](const Json& value) -> std::string {
            if (!value.is_string() || !parseSamplerKind(value.get<std::string>().c_str(), *field)) {
                return "must be \"sobol\" or \"independent\", got " + shown(value);
            }
            return {};
        };
    }

    bool section(const std::string& name, const Json& value, std::initializer_list<Field> fields) {
        if (!value.is_object()) {
            return fail(name, "must be an object, got " + shown(value));
        }
        for (const auto& [key, child] : value.items()) {
            const Field* field = nullptr;
            for (const Field& f : fields) {
                if (key == f.name) {
                    field = &f;
                }
            }
            if (field == nullptr) {
                return fail(name + "." + key, "unknown key");
            }
            if (!leaf(name + "." + key, child, field->set)) {
                return false;
            }
        }
        return true;
    }

    bool leaf(const std::string& key, const Json& value, const Setter& set) {
        if (std::string why = set(value); !why.empty()) {
            return fail(key, why);
        }
        if (startedValid_) {
            if (std::string why = validate(work_); !why.empty()) {
                return fail(key, why);
            }
        }
        extras_.keys.insert(key);
        return true;
    }

    bool fail(const std::string& key, const std::string& why) {
        error_ = key.empty() ? why : key + ": " + why;
        return false;
    }

    RenderSettings work_;
    SettingsJsonExtras& extras_;
    std::string& error_;
    bool startedValid_;
};

// Settings files are small; anything larger (or a device such as /dev/zero that never ends) is
// refused instead of read.
constexpr std::size_t kMaxSettingsBytes = 16u << 20;

} // namespace

bool CameraBookmarks::any() const {
    for (const std::optional<Camera>& c : slots) {
        if (c) {
            return true;
        }
    }
    return false;
}

std::string settingsToJson(const RenderSettings& settings) {
    return toJson(settings).dump(2) + "\n";
}

std::string settingsToJson(const RenderSettings& settings, const std::string& scene) {
    OrderedJson j = toJson(settings);
    if (!scene.empty()) {
        j["scene"] = scene;
    }
    return j.dump(2) + "\n";
}

std::string settingsToJson(const RenderSettings& settings, const std::string& scene,
                           const SettingsFileExtras& extras) {
    OrderedJson j = toJson(settings);
    if (!scene.empty()) {
        j["scene"] = scene;
    }
    if (extras.split) {
        const SplitRecord& split = *extras.split;
        j["split"] = {{"divider", shortFloat(split.divider)}, {"side", split.side}};
        if (!split.other.empty()) {
            j["split"]["other"] = split.other;
        }
        if (split.difference > 0.0f) {
            j["split"]["difference"] = shortFloat(split.difference);
        }
    }
    const auto cameraJson = [](const Camera& c) {
        return OrderedJson{{"position", vec3Json(c.position)},
                           {"yaw", shortFloat(c.yawDegrees)},
                           {"pitch", shortFloat(c.pitchDegrees)},
                           {"fov", shortFloat(c.verticalFovDegrees)}};
    };
    if (extras.bookmarks.any()) {
        OrderedJson slots = OrderedJson::array();
        for (const std::optional<Camera>& c : extras.bookmarks.slots) {
            slots.push_back(c ? cameraJson(*c) : OrderedJson(nullptr));
        }
        j["bookmarks"] = std::move(slots);
    }
    if (!extras.frames.empty()) {
        OrderedJson frames = OrderedJson::array();
        for (const Camera& c : extras.frames) {
            frames.push_back(cameraJson(c));
        }
        j["frames"] = std::move(frames);
    }
    if (extras.observedLabCamera) {
        j["observer"] = {{"lab_camera", cameraJson(*extras.observedLabCamera)}};
    }
    return j.dump(2) + "\n";
}

bool settingsFromJson(const std::string& text, RenderSettings& settings, SettingsJsonExtras& extras,
                      std::string& error) {
    const SingleLineOnExit oneLine(error);
    Json root;
    try {
        root = Json::parse(text);
    } catch (const Json::exception& e) {
        error = jsonParseError(e.what());
        return false;
    }
    SettingsJsonExtras found;
    Reader reader(settings, found, error);
    if (!reader.read(root)) {
        return false;
    }
    if (std::string why = validate(reader.result()); !why.empty()) {
        error = why;
        return false;
    }
    settings = reader.result();
    extras = std::move(found);
    return true;
}

bool settingsFromJson(const std::string& text, RenderSettings& settings, std::string& error) {
    SettingsJsonExtras extras;
    return settingsFromJson(text, settings, extras, error);
}

bool loadSettingsFile(const std::string& path, RenderSettings& settings, SettingsJsonExtras& extras,
                      std::string& error) {
    const SingleLineOnExit oneLine(error);
    std::string text;
    if (!readRegularTextFile(path, "settings", kMaxSettingsBytes, text, error)) {
        return false;
    }
    std::string why;
    if (!settingsFromJson(text, settings, extras, why)) {
        error = path + ": " + why;
        return false;
    }
    return true;
}

bool loadSettingsFile(const std::string& path, RenderSettings& settings, std::string& error) {
    SettingsJsonExtras extras;
    return loadSettingsFile(path, settings, extras, error);
}

bool saveSettingsFile(const std::string& path, const RenderSettings& settings,
                      const std::string& scene, std::string& error) {
    const std::string text = settingsToJson(settings, scene);
    return writeFileAtomically(
        path,
        [&text](std::FILE* file, std::string&) {
            return std::fwrite(text.data(), 1, text.size(), file) == text.size();
        },
        error);
}

bool saveSettingsFile(const std::string& path, const RenderSettings& settings,
                      const std::string& scene, const SettingsFileExtras& extras,
                      std::string& error) {
    const std::string text = settingsToJson(settings, scene, extras);
    return writeFileAtomically(
        path,
        [&text](std::FILE* file, std::string&) {
            return std::fwrite(text.data(), 1, text.size(), file) == text.size();
        },
        error);
}

bool saveSettingsFile(const std::string& path, const RenderSettings& settings, std::string& error) {
    return saveSettingsFile(path, settings, std::string(), error);
}

} // namespace raylab
