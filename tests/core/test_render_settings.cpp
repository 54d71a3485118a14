// Settings validation: the lab's defaults pass, every nonsensical value is named.

#include "core/render_settings.h"

#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <utility>
#include <vector>

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

TEST(RenderSettings, DifferencesNameEveryFieldThatDiffers) {
    const RenderSettings a;
    EXPECT_TRUE(settingsDifferences(a, a).empty());
    // One change of each field: exactly one line, naming it.
    const std::vector<std::pair<const char*, void (*)(RenderSettings&)>> changes = {
        {"camera position", [](RenderSettings& s) { s.camera.position.x = 1.0f; }},
        {"yaw", [](RenderSettings& s) { s.camera.yawDegrees = 3.0f; }},
        {"pitch", [](RenderSettings& s) { s.camera.pitchDegrees = 3.0f; }},
        {"field of view", [](RenderSettings& s) { s.camera.verticalFovDegrees = 40.0f; }},
        {"light position", [](RenderSettings& s) { s.light.position.y = 0.1f; }},
        {"light colour", [](RenderSettings& s) { s.light.color.x = 0.5f; }},
        {"light power", [](RenderSettings& s) { s.light.intensity = 2.0f; }},
        {"light radius", [](RenderSettings& s) { s.light.radius = 0.1f; }},
        {"indirect", [](RenderSettings& s) { s.indirect = false; }},
        {"indirect colour", [](RenderSettings& s) { s.indirectColor.z = 0.2f; }},
        {"indirect N", [](RenderSettings& s) { s.indirectIntensity = 0.2f; }},
        {"shadows", [](RenderSettings& s) { s.shadows = false; }},
        {"shadow epsilon", [](RenderSettings& s) { s.shadowEpsilon = 0.0f; }},
        {"width", [](RenderSettings& s) { s.width = 7; }},
        {"height", [](RenderSettings& s) { s.height = 7; }},
        {"sample cap", [](RenderSettings& s) { s.samplesPerPixel = 7; }},
        {"threads", [](RenderSettings& s) { s.threads = 7; }},
        {"display", [](RenderSettings& s) { s.display = DisplayMode::Srgb; }},
        {"exposure", [](RenderSettings& s) { s.exposure = 1.0f; }},
        {"integrator", [](RenderSettings& s) { s.integrator = Integrator::Path; }},
        {"max bounces", [](RenderSettings& s) { s.maxBounces = 2; }},
        {"emission scale", [](RenderSettings& s) { s.emissionScale = 2.0f; }},
        {"sampler", [](RenderSettings& s) { s.sampler = SamplerKind::Independent; }},
        {"view", [](RenderSettings& s) { s.view = View::Depth; }},
    };
    for (const auto& [name, change] : changes) {
        RenderSettings b = a;
        change(b);
        ASSERT_NE(a, b) << name;
        const std::vector<std::string> lines = settingsDifferences(a, b);
        ASSERT_EQ(lines.size(), 1u) << name;
        EXPECT_EQ(lines[0].rfind(name, 0), 0u) << lines[0];
    }
    // Every field of the struct is one of those: a field added without a line fails here.
    EXPECT_EQ(changes.size(), 24u);
    static_assert(sizeof(RenderSettings) == 128, "a field was added: give it a line in "
                                                 "settingsDifferences and a change above");
}

} // namespace
} // namespace raylab
