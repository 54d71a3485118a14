// The false-colour display (render/false_colour.h): the logarithmic scale's ends and middle, its
// colours, black for values with no colour, and toRgba8 writing exactly displayPixel's bytes.

#include "core/render/display_transform.h"
#include "core/render/false_colour.h"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace raylab {
namespace {

TEST(FalseColour, TheScaleSpansSixteenStopsAboutTwoToTheExposure) {
    for (float exposure : {0.0f, -3.0f, 5.5f}) {
        EXPECT_FLOAT_EQ(falseColourPosition(std::exp2(exposure), exposure), 0.5f);
        EXPECT_FLOAT_EQ(falseColourPosition(std::exp2(exposure - 8.0f), exposure), 0.0f);
        EXPECT_FLOAT_EQ(falseColourPosition(std::exp2(exposure + 8.0f), exposure), 1.0f);
        EXPECT_FLOAT_EQ(falseColourPosition(std::exp2(exposure + 4.0f), exposure), 0.75f);
        EXPECT_FLOAT_EQ(falseColourPosition(1e30f, exposure), 1.0f); // past the end
        EXPECT_FLOAT_EQ(falseColourPosition(1e-30f, exposure), 0.0f);
        for (float t : {0.0f, 0.3f, 0.5f, 1.0f}) {
            EXPECT_NEAR(falseColourPosition(falseColourValue(t, exposure), exposure), t, 1e-6f);
        }
    }
    EXPECT_LT(falseColourPosition(0.0f, 0.0f), 0.0f);
    EXPECT_LT(falseColourPosition(-1.0f, 0.0f), 0.0f);
    EXPECT_LT(falseColourPosition(std::nanf(""), 0.0f), 0.0f);
}

TEST(FalseColour, DarkBlueToWhiteAndBlackForNoValue) {
    EXPECT_EQ(falseColourAt(0.0f), (std::array<uint8_t, 3>{0, 0, 64}));
    EXPECT_EQ(falseColourAt(0.5f), (std::array<uint8_t, 3>{32, 200, 64}));
    EXPECT_EQ(falseColourAt(1.0f), (std::array<uint8_t, 3>{255, 255, 255}));
    EXPECT_EQ(falseColour(glm::vec3(0.0f), 0.0f), (std::array<uint8_t, 3>{0, 0, 0}));
    EXPECT_EQ(falseColour(glm::vec3(-2.0f, 0.0f, std::nanf("")), 0.0f),
              (std::array<uint8_t, 3>{0, 0, 0}));
    // The largest channel decides: a red pixel of 1 is the middle's colour.
    EXPECT_EQ(falseColour(glm::vec3(1.0f, 0.01f, 0.0f), 0.0f), falseColourAt(0.5f));
    // Brighter is warmer: red rises and blue falls from the middle to the bright end.
    EXPECT_GT(falseColourAt(0.8f)[0], falseColourAt(0.6f)[0]);
    EXPECT_LT(falseColourAt(0.8f)[2], falseColourAt(0.2f)[2]);
}

TEST(FalseColour, ToRgba8WritesDisplayPixelsBytes) {
    std::vector<glm::vec3> values;
    for (int i = -20; i < 20; ++i) {
        values.emplace_back(std::exp2(static_cast<float>(i) * 0.7f), 0.5f,
                            i % 3 == 0 ? -1.0f : 2.0f);
    }
    values.emplace_back(0.0f);
    std::vector<uint8_t> rgba(4 * values.size());
    toRgba8(values, 2.0f, DisplayMode::FalseColour, 1.5f, rgba, PixelOrder::Bgra);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::array<uint8_t, 3> expected =
            displayPixel(values[i] * 2.0f, DisplayMode::FalseColour, 1.5f);
        EXPECT_EQ(rgba[4 * i + 2], expected[0]) << i;
        EXPECT_EQ(rgba[4 * i + 1], expected[1]) << i;
        EXPECT_EQ(rgba[4 * i + 0], expected[2]) << i;
        EXPECT_EQ(rgba[4 * i + 3], 255);
        EXPECT_EQ(expected, falseColour(values[i] * 2.0f, 1.5f));
    }
}

} // namespace
} // namespace raylab
