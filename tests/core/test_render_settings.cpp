// Settings validation: the lab's defaults pass, every nonsensical value is named.

#include "core/render_settings.h"

#include <gtest/gtest.h>
#include <limits>

namespace raylab {
namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

TEST(RenderSettings, LabDefaultsAreValidAndMatchTheLab) {
    const RenderSettings s;
    EXPECT_EQ(validate(s), "");
    EXPECT_EQ(s.light.position, glm::vec3(0.0f, 0.5f, -0.7f));
    EXPECT_EQ(s.light.power(), glm::vec3(14.0f));
    EXPECT_EQ(s.indirect3(), glm::vec3(0.5f));
    EXPECT_EQ(s.shadowEpsilon, 1e-3f);
    EXPECT_EQ(s.width, 500);
    EXPECT_EQ(s.height, 500);
    EXPECT_EQ(s.display, DisplayMode::Lab);
}

TEST(RenderSettings, IndirectOffMeansNoIndirectTerm) {
    RenderSettings s;
    s.indirect = false;
    EXPECT_EQ(s.indirect3(), glm::vec3(0.0f));
}

struct BadCase {
    const char* expectedWords;
    void (*apply)(RenderSettings&);
};

TEST(RenderSettings, EachNonsensicalValueIsRefusedWithItsName) {
    const BadCase cases[] = {
        {"camera position", [](RenderSettings& s) { s.camera.position.y = kNaN; }},
        {"yaw", [](RenderSettings& s) { s.camera.yawDegrees = kInf; }},
        {"pitch", [](RenderSettings& s) { s.camera.pitchDegrees = 90.0f; }},
        {"pitch", [](RenderSettings& s) { s.camera.pitchDegrees = kNaN; }},
        {"field of view", [](RenderSettings& s) { s.camera.verticalFovDegrees = 0.0f; }},
        {"field of view", [](RenderSettings& s) { s.camera.verticalFovDegrees = 180.0f; }},
        {"field of view", [](RenderSettings& s) { s.camera.verticalFovDegrees = kNaN; }},
        {"light position", [](RenderSettings& s) { s.light.position.x = -kInf; }},
        {"light colour", [](RenderSettings& s) { s.light.color.z = -0.1f; }},
        {"light power", [](RenderSettings& s) { s.light.intensity = -1.0f; }},
        {"light power", [](RenderSettings& s) { s.light.intensity = kNaN; }},
        {"indirect colour", [](RenderSettings& s) { s.indirectColor.x = kNaN; }},
        {"indirect light", [](RenderSettings& s) { s.indirectIntensity = -0.5f; }},
        {"shadow epsilon", [](RenderSettings& s) { s.shadowEpsilon = -1e-3f; }},
        {"shadow epsilon", [](RenderSettings& s) { s.shadowEpsilon = kNaN; }},
        {"image size", [](RenderSettings& s) { s.width = 0; }},
        {"image size", [](RenderSettings& s) { s.height = kMaxImageSide + 1; }},
        {"samples per pixel", [](RenderSettings& s) { s.samplesPerPixel = 0; }},
        {"threads", [](RenderSettings& s) { s.threads = -2; }},
        {"exposure", [](RenderSettings& s) { s.exposure = kNaN; }},
    };
    for (const BadCase& c : cases) {
        RenderSettings s;
        c.apply(s);
        const std::string error = validate(s);
        EXPECT_NE(error.find(c.expectedWords), std::string::npos)
            << "expected '" << c.expectedWords << "' in '" << error << "'";
        EXPECT_EQ(error.find('\n'), std::string::npos) << "one line";
    }
}

TEST(RenderSettings, ZeroPowerZeroEpsilonAndZeroIndirectAreAllowed) {
    RenderSettings s;
    s.light.intensity = 0.0f;
    s.shadowEpsilon = 0.0f;
    s.indirectIntensity = 0.0f;
    EXPECT_EQ(validate(s), "");
}

TEST(RenderSettings, DisplayModeNamesRoundTrip) {
    DisplayMode mode = DisplayMode::Lab;
    EXPECT_TRUE(parseDisplayMode("srgb", mode));
    EXPECT_EQ(mode, DisplayMode::Srgb);
    EXPECT_STREQ(toString(mode), "srgb");
    EXPECT_TRUE(parseDisplayMode(toString(DisplayMode::Lab), mode));
    EXPECT_EQ(mode, DisplayMode::Lab);
    EXPECT_FALSE(parseDisplayMode("SRGB ", mode));
    EXPECT_FALSE(parseDisplayMode("", mode));
}

} // namespace
} // namespace raylab
