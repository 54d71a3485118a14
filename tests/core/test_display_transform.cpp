// Display transforms: the lab's clamp and sRGB with exposure.

#include "core/display_transform.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace raylab {
namespace {

TEST(DisplayTransform, LabClampsAndScalesWithoutGamma) {
    EXPECT_EQ(displayChannel(0.0f, DisplayMode::Lab, 0.0f), 0);
    EXPECT_EQ(displayChannel(-3.0f, DisplayMode::Lab, 0.0f), 0);
    EXPECT_EQ(displayChannel(0.5f, DisplayMode::Lab, 0.0f), 128); // 127.5 rounds up
    EXPECT_EQ(displayChannel(0.2f, DisplayMode::Lab, 0.0f), 51);
    EXPECT_EQ(displayChannel(1.0f, DisplayMode::Lab, 0.0f), 255);
    EXPECT_EQ(displayChannel(7.0f, DisplayMode::Lab, 0.0f), 255);
    EXPECT_EQ(displayChannel(0.5f, DisplayMode::Lab, 3.0f), 128) << "exposure is sRGB only";
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::quiet_NaN(), DisplayMode::Lab, 0.0f), 0);
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::infinity(), DisplayMode::Lab, 0.0f), 255);
}

TEST(DisplayTransform, SrgbFollowsTheTransferCurveAndExposure) {
    EXPECT_EQ(displayChannel(0.0f, DisplayMode::Srgb, 0.0f), 0);
    EXPECT_EQ(displayChannel(1.0f, DisplayMode::Srgb, 0.0f), 255);
    // 0.22 linear is 0.5064 in sRGB: 129.13 of 255.
    EXPECT_EQ(displayChannel(0.22f, DisplayMode::Srgb, 0.0f), 129);
    EXPECT_EQ(displayChannel(0.5f, DisplayMode::Srgb, 0.0f), 188); // 187.52
    // The linear segment near black: 0.001 -> 12.92 * 0.001 * 255 = 3.29.
    EXPECT_EQ(displayChannel(0.001f, DisplayMode::Srgb, 0.0f), 3);
    // One stop of exposure doubles the linear value.
    EXPECT_EQ(displayChannel(0.11f, DisplayMode::Srgb, 1.0f), 129);
    EXPECT_EQ(displayChannel(0.44f, DisplayMode::Srgb, -1.0f), 129);
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::quiet_NaN(), DisplayMode::Srgb, 0.0f), 0);
}

TEST(DisplayTransform, ImagesBecomeRowMajorRgbaWithOpaqueAlpha) {
    Framebuffer image(2, 1);
    image.at(0, 0) = {1.0f, 0.0f, 0.5f};
    image.at(1, 0) = {0.2f, 2.0f, -1.0f};
    const std::vector<uint8_t> rgba = toRgba8(image, DisplayMode::Lab, 0.0f);
    const std::vector<uint8_t> expected = {255, 0, 128, 255, 51, 255, 0, 255};
    EXPECT_EQ(rgba, expected);

    // The scale divides an accumulation buffer of sums by its sample count.
    std::vector<glm::vec3> sums = {{2.0f, 1.0f, 0.4f}};
    std::vector<uint8_t> out(4);
    toRgba8(sums, 0.5f, DisplayMode::Lab, 0.0f, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{255, 128, 51, 255}));
}

} // namespace
} // namespace raylab
