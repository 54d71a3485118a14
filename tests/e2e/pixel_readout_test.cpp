// The panel's readouts without a window: a pixel's linear value and displayed bytes, and the mean
// of a rectangle of pixels.

#include "pixel_readout.h"

#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

// A 4 x 3 picture: linear (x, y, x + 10 y), bytes B = x, G = y, R = 100 + x.
ShownImage picture() {
    ShownImage shown;
    shown.linear = Framebuffer(4, 3);
    shown.bgra.width = 4;
    shown.bgra.height = 3;
    shown.bgra.pixels.resize(4 * 4 * 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 4; ++x) {
            shown.linear.at(x, y) = {static_cast<float>(x), static_cast<float>(y),
                                     static_cast<float>(x + 10 * y)};
            const std::size_t at = 4 * static_cast<std::size_t>(y * 4 + x);
            shown.bgra.pixels[at] = static_cast<uint8_t>(x);
            shown.bgra.pixels[at + 1] = static_cast<uint8_t>(y);
            shown.bgra.pixels[at + 2] = static_cast<uint8_t>(100 + x);
            shown.bgra.pixels[at + 3] = 255;
        }
    }
    return shown;
}

TEST(PixelReadout, APixelGivesItsLinearValueAndItsBytesAsRgb) {
    const ShownImage shown = picture();
    const auto read = readPixel(shown, 3, 2);
    ASSERT_TRUE(read);
    EXPECT_EQ(read->x, 3);
    EXPECT_EQ(read->y, 2);
    EXPECT_EQ(read->linear, glm::vec3(3.0f, 2.0f, 23.0f));
    EXPECT_EQ(read->display, (std::array<uint8_t, 3>{103, 2, 3}));
}

TEST(PixelReadout, NothingOutsideThePictureOrWithoutItsLinearValues) {
    ShownImage shown = picture();
    EXPECT_FALSE(readPixel(shown, 4, 0));
    EXPECT_FALSE(readPixel(shown, 0, 3));
    EXPECT_FALSE(readPixel(shown, -1, 0));
    shown.preview = true; // a preview's bytes are upscaled, its values not kept
    EXPECT_FALSE(readPixel(shown, 0, 0));
    shown.preview = false;
    shown.linear = Framebuffer();
    EXPECT_FALSE(readPixel(shown, 0, 0));
}

TEST(PixelReadout, ARectanglesMeanCountsBothCornersInEitherOrder) {
    const ShownImage shown = picture();
    // Columns 1..2, rows 0..1: x mean 1.5, y mean 0.5, x + 10 y mean 6.5.
    for (const PixelRectangle r : {PixelRectangle{1, 0, 2, 1}, PixelRectangle{2, 1, 1, 0}}) {
        const auto mean = rectangleMean(shown.linear, r);
        ASSERT_TRUE(mean);
        EXPECT_EQ(mean->pixels, 4);
        EXPECT_EQ(mean->rectangle, (PixelRectangle{1, 0, 2, 1}));
        EXPECT_DOUBLE_EQ(mean->mean.x, 1.5);
        EXPECT_DOUBLE_EQ(mean->mean.y, 0.5);
        EXPECT_DOUBLE_EQ(mean->mean.z, 6.5);
    }
    // One pixel is its own mean.
    const auto one = rectangleMean(shown.linear, {3, 2, 3, 2});
    ASSERT_TRUE(one);
    EXPECT_EQ(one->pixels, 1);
    EXPECT_DOUBLE_EQ(one->mean.z, 23.0);
}

TEST(PixelReadout, ARectangleIsCutToThePicture) {
    const ShownImage shown = picture();
    const auto mean = rectangleMean(shown.linear, {-5, -5, 100, 100});
    ASSERT_TRUE(mean);
    EXPECT_EQ(mean->pixels, 12);
    EXPECT_EQ(mean->rectangle, (PixelRectangle{0, 0, 3, 2}));
    EXPECT_DOUBLE_EQ(mean->mean.x, 1.5);
    EXPECT_DOUBLE_EQ(mean->mean.y, 1.0);
    EXPECT_FALSE(rectangleMean(shown.linear, {5, 0, 9, 2}));
}

} // namespace
} // namespace raylab::viewer
