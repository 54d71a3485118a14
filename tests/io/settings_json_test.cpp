// Settings JSON: exact round trips, partial documents, and an error naming the key for each kind
// of bad value.

#include "io/settings_json.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>

namespace raylab {
namespace {

namespace fs = std::filesystem;

// Bitwise equality of every field (so -0 vs 0 or a last-bit difference shows).
bool sameBits(float a, float b) { return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b); }
bool sameBits(const glm::vec3& a, const glm::vec3& b) {
    return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

void expectSame(const RenderSettings& a, const RenderSettings& b) {
    EXPECT_TRUE(sameBits(a.camera.position, b.camera.position));
    EXPECT_TRUE(sameBits(a.camera.yawDegrees, b.camera.yawDegrees));
    EXPECT_TRUE(sameBits(a.camera.pitchDegrees, b.camera.pitchDegrees));
    EXPECT_TRUE(sameBits(a.camera.verticalFovDegrees, b.camera.verticalFovDegrees));
    EXPECT_TRUE(sameBits(a.light.position, b.light.position));
    EXPECT_TRUE(sameBits(a.light.color, b.light.color));
    EXPECT_TRUE(sameBits(a.light.intensity, b.light.intensity));
    EXPECT_EQ(a.indirect, b.indirect);
    EXPECT_TRUE(sameBits(a.indirectColor, b.indirectColor));
    EXPECT_TRUE(sameBits(a.indirectIntensity, b.indirectIntensity));
    EXPECT_EQ(a.shadows, b.shadows);
    EXPECT_TRUE(sameBits(a.shadowEpsilon, b.shadowEpsilon));
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.samplesPerPixel, b.samplesPerPixel);
    EXPECT_EQ(a.threads, b.threads);
    EXPECT_EQ(a.display, b.display);
    EXPECT_TRUE(sameBits(a.exposure, b.exposure));
}

RenderSettings unusual() {
    RenderSettings s;
    s.camera.position = glm::vec3(0.1f, -1.0f / 3.0f, 1e-7f);
    s.camera.yawDegrees = -123.456789f;
    s.camera.pitchDegrees = 89.99f;
    s.camera.verticalFovDegrees = 0.5f;
    s.light.position = glm::vec3(3.4028e38f, -0.0f, 7.0f);
    s.light.color = glm::vec3(0.3f, 1.0f, 0.0f);
    s.light.intensity = 1234.5678f;
    s.indirect = false;
    s.indirectColor = glm::vec3(1.0f, 0.2f, 0.7f);
    s.indirectIntensity = 0.0f;
    s.shadows = false;
    s.shadowEpsilon = 0.0f;
    s.width = 16384;
    s.height = 1;
    s.samplesPerPixel = 64;
    s.threads = 3;
    s.display = DisplayMode::Srgb;
    s.exposure = -2.5f;
    return s;
}

TEST(SettingsJson, DefaultsRoundTrip) {
    const RenderSettings defaults;
    RenderSettings back = unusual();
    std::string error;
    ASSERT_TRUE(settingsFromJson(settingsToJson(defaults), back, error)) << error;
    expectSame(back, defaults);
}

TEST(SettingsJson, UnusualValuesRoundTripExactly) {
    const RenderSettings s = unusual();
    RenderSettings back;
    std::string error;
    ASSERT_TRUE(settingsFromJson(settingsToJson(s), back, error)) << error;
    expectSame(back, s);
}

TEST(SettingsJson, RandomFloatsRoundTripBitForBit) {
    std::mt19937 rng(99);
    RenderSettings s;
    for (int i = 0; i < 20000; ++i) {
        // Any finite float bit pattern, for a field that takes any finite value.
        float f = 0.0f;
        do {
            f = std::bit_cast<float>(static_cast<uint32_t>(rng()));
        } while (!std::isfinite(f));
        s.camera.yawDegrees = f;
        s.camera.position.x = f;
        RenderSettings back;
        std::string error;
        ASSERT_TRUE(settingsFromJson(settingsToJson(s), back, error)) << error;
        ASSERT_TRUE(sameBits(back.camera.yawDegrees, f)) << f;
        ASSERT_TRUE(sameBits(back.camera.position.x, f)) << f;
    }
}

TEST(SettingsJson, ShortDecimalsAreWrittenShort) {
    RenderSettings s;
    s.light.position = glm::vec3(0.1f, 0.5f, -0.7f);
    const std::string json = settingsToJson(s);
    EXPECT_NE(json.find("-0.7"), std::string::npos) << json;
    EXPECT_EQ(json.find("0.699999"), std::string::npos) << json;
    EXPECT_NE(json.find("\"fov\": 53.130104"), std::string::npos) << json;
    EXPECT_NE(json.find("\"mode\": \"lab\""), std::string::npos) << json;
}

TEST(SettingsJson, PartialDocumentKeepsOtherValues) {
    RenderSettings s = unusual();
    const RenderSettings before = s;
    std::string error;
    ASSERT_TRUE(
        settingsFromJson(R"({"light": {"intensity": 3}, "image": {"width": 64}})", s, error))
        << error;
    EXPECT_EQ(s.light.intensity, 3.0f);
    EXPECT_EQ(s.width, 64);
    s.light.intensity = before.light.intensity;
    s.width = before.width;
    expectSame(s, before);
    EXPECT_TRUE(settingsFromJson("{}", s, error)) << error;
}

TEST(SettingsJson, ExtrasListTheKeysAndTheScene) {
    RenderSettings s;
    SettingsJsonExtras extras;
    std::string error;
    ASSERT_TRUE(settingsFromJson(R"({"camera": {"yaw": 10}, "threads": 2, "scene": "bunny.ply"})",
                                 s, extras, error))
        << error;
    EXPECT_EQ(extras.keys, (std::set<std::string>{"camera.yaw", "threads", "scene"}));
    EXPECT_EQ(extras.scene, "bunny.ply");
    const std::string withScene = settingsToJson(s, "bunny.ply");
    EXPECT_NE(withScene.find("\"scene\": \"bunny.ply\""), std::string::npos);
    EXPECT_EQ(settingsToJson(s).find("scene"), std::string::npos);
}

TEST(SettingsJson, ObserverRecordKeepsTheLabCameraBitForBit) {
    SettingsFileExtras file;
    Camera lab;
    lab.position = {0.1f, -2.0f / 3.0f, -3.0f};
    lab.yawDegrees = 12.345678f;
    lab.pitchDegrees = -7.0f / 3.0f;
    lab.verticalFovDegrees = kLabVerticalFovDegrees;
    file.observedLabCamera = lab;
    RenderSettings observer;
    observer.camera.position = {1.0f, 2.0f, -6.0f};
    const std::string text = settingsToJson(observer, "cornell", file);
    RenderSettings read;
    SettingsJsonExtras extras;
    std::string error;
    ASSERT_TRUE(settingsFromJson(text, read, extras, error)) << error;
    ASSERT_TRUE(extras.observedLabCamera.has_value());
    EXPECT_TRUE(sameBits(extras.observedLabCamera->position, lab.position));
    EXPECT_TRUE(sameBits(extras.observedLabCamera->yawDegrees, lab.yawDegrees));
    EXPECT_TRUE(sameBits(extras.observedLabCamera->pitchDegrees, lab.pitchDegrees));
    EXPECT_TRUE(sameBits(extras.observedLabCamera->verticalFovDegrees, lab.verticalFovDegrees));
    EXPECT_EQ(read.camera, observer.camera); // the picture's camera is the observer's
    EXPECT_EQ(extras.keys.count("observer"), 1u);
    EXPECT_EQ(settingsToJson(observer, "cornell", SettingsFileExtras{}).find("observer"),
              std::string::npos);
    EXPECT_FALSE(
        settingsFromJson(R"({"observer": {"lab_camera": {"fov": 200}}})", read, extras, error));
    EXPECT_NE(error.find("observer.lab_camera"), std::string::npos) << error;
    EXPECT_FALSE(settingsFromJson(R"({"observer": {}})", read, extras, error));
    EXPECT_NE(error.find("observer: must be"), std::string::npos) << error;
}

struct BadCase {
    const char* json;
    const char* mustContain; // in the error
};

TEST(SettingsJson, EachErrorNamesTheKeyAndChangesNothing) {
    const BadCase cases[] = {
        {R"({"camera": {"fov": "wide"}})", "camera.fov: must be a number"},
        {R"({"camera": {"zoom": 2}})", "camera.zoom: unknown key"},
        {R"({"colour": 1})", "colour: unknown key"},
        {R"({"camera": {"position": [1, 2]}})", "camera.position: must be an array of 3"},
        {R"({"camera": {"position": [1, 2, "x"]}})", "camera.position"},
        {R"({"camera": {"position": [1, 2, null]}})", "camera.position"},
        {R"({"camera": 5})", "camera: must be an object"},
        {R"({"light": {"intensity": 1e999}})", "1e999"}, // nlohmann: number overflow
        {R"({"light": {"intensity": 1e39}})", "light.intensity: must be a finite number"},
        {R"({"light": {"intensity": -1}})", "light.intensity"},
        {R"({"light": {"color": [-1, 0, 0]}})", "light.color"},
        {R"({"display": {"exposure": 100}})", "display.exposure"},
        {R"({"camera": {"fov": 180}})", "camera.fov"},
        {R"({"camera": {"pitch": 90}})", "camera.pitch"},
        {R"({"shadows": {"epsilon": -0.1}})", "shadows.epsilon"},
        {R"({"shadows": {"enabled": 1}})", "shadows.enabled: must be true or false"},
        {R"({"image": {"width": 0}})", "image.width"},
        {R"({"image": {"width": 16385}})", "image.width"},
        {R"({"image": {"width": 500.5}})", "image.width: must be an integer"},
        {R"({"image": {"height": 99999999999}})", "image.height: is out of range"},
        {R"({"image": {"samples": 0}})", "image.samples"},
        {R"({"threads": -1})", "threads"},
        {R"({"display": {"mode": "hdr"}})", "display.mode: must be \"lab\" or \"srgb\""},
        {R"({"scene": 3})", "scene: must be a non-empty string"},
        {R"([1, 2, 3])", "must be a JSON object"},
        {R"({"threads": 1,})", "invalid JSON"},
        {R"({"threads": NaN})", "invalid JSON"},
        {"", "invalid JSON"},
    };
    for (const BadCase& c : cases) {
        RenderSettings s = unusual();
        std::string error;
        EXPECT_FALSE(settingsFromJson(c.json, s, error)) << c.json;
        EXPECT_NE(error.find(c.mustContain), std::string::npos) << c.json << " gave: " << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        expectSame(s, unusual());
    }
}

TEST(SettingsJson, FilesRoundTripAndErrorsNameThePath) {
    const fs::path dir = fs::temp_directory_path() / "raylab-settings-json-test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string file = (dir / "s.json").string();
    std::string error;
    ASSERT_TRUE(saveSettingsFile(file, unusual(), "cornell", error)) << error;
    RenderSettings back;
    SettingsJsonExtras extras;
    ASSERT_TRUE(loadSettingsFile(file, back, extras, error)) << error;
    expectSame(back, unusual());
    EXPECT_EQ(extras.scene, "cornell");

    std::ofstream(dir / "bad.json") << R"({"light": {"intensity": "lots"}})";
    EXPECT_FALSE(loadSettingsFile((dir / "bad.json").string(), back, error));
    EXPECT_EQ(error.rfind((dir / "bad.json").string() + ": light.intensity", 0), 0u) << error;

    EXPECT_FALSE(loadSettingsFile((dir / "none.json").string(), back, error));
    EXPECT_NE(error.find("No such file"), std::string::npos) << error;

    EXPECT_FALSE(saveSettingsFile((dir / "no/such/dir.json").string(), back, error));
    EXPECT_NE(error.find("dir.json"), std::string::npos) << error;
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) {
        ++count;
    }
    EXPECT_EQ(count, 2u); // s.json and bad.json, no temporary files
    fs::remove_all(dir);
}

} // namespace
} // namespace raylab
