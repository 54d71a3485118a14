// The window's layout without a window: the panel's column beside the picture, shown or hidden,
// in narrow windows, and the mouse mapped to the picture's pixels at its edges.

#include "view_layout.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <optional>
#include <utility>

namespace raylab::viewer {
namespace {

TEST(ViewLayout, ThePanelTakesItsColumnAndThePictureTheRest) {
    const ViewLayout layout = viewLayout(840, 360, true, 360, 200);
    EXPECT_TRUE(layout.panelShown());
    EXPECT_EQ(layout.panel, (PixelBox{0, 0, 360, 360}));
    EXPECT_EQ(layout.picture, (PixelBox{360, 0, 480, 360}));
    EXPECT_EQ(layout.framebufferWidth, 840);
    EXPECT_EQ(layout.framebufferHeight, 360);
}

TEST(ViewLayout, AHiddenPanelLeavesTheWholeFramebufferToThePicture) {
    const ViewLayout layout = viewLayout(840, 360, false, 360, 200);
    EXPECT_FALSE(layout.panelShown());
    EXPECT_TRUE(layout.panel.empty());
    EXPECT_EQ(layout.picture, (PixelBox{0, 0, 840, 360}));
}

TEST(ViewLayout, ANarrowWindowShrinksThePanelAndKeepsAPixelOfPicture) {
    // Narrower than the panel's width: the panel gives way, down to its minimum.
    ViewLayout layout = viewLayout(300, 200, true, 360, 200);
    EXPECT_EQ(layout.panel, (PixelBox{0, 0, 299, 200}));
    EXPECT_EQ(layout.picture, (PixelBox{299, 0, 1, 200}));
    layout = viewLayout(201, 200, true, 360, 200);
    EXPECT_EQ(layout.panel.width, 200);
    EXPECT_EQ(layout.picture, (PixelBox{200, 0, 1, 200}));
    // Too narrow for the minimum and a pixel: no panel, the picture takes everything.
    layout = viewLayout(200, 200, true, 360, 200);
    EXPECT_FALSE(layout.panelShown());
    EXPECT_EQ(layout.picture, (PixelBox{0, 0, 200, 200}));
    layout = viewLayout(1, 1, true, 360, 200);
    EXPECT_FALSE(layout.panelShown());
    EXPECT_EQ(layout.picture, (PixelBox{0, 0, 1, 1}));
}

TEST(ViewLayout, AnEmptyFramebufferGivesEmptyBoxes) {
    for (const auto& [w, h] : {std::pair{0, 0}, std::pair{0, 100}, std::pair{100, 0}}) {
        const ViewLayout layout = viewLayout(w, h, true, 360, 200);
        EXPECT_TRUE(layout.picture.empty());
        EXPECT_TRUE(layout.panel.empty());
    }
    EXPECT_TRUE(viewLayout(-5, 10, false, 0, 0).picture.empty());
}

// pixelUnderCursor's pixel, or nothing when it says the point is outside.
std::optional<std::pair<int, int>> under(double x, double y, const PixelBox& picture, int width,
                                         int height) {
    int px = -1, py = -1;
    if (!pixelUnderCursor(x, y, picture, width, height, px, py)) {
        return std::nullopt;
    }
    return std::pair(px, py);
}

TEST(ViewLayout, TheCursorMapsToThePicturesPixelsOnlyInsideIt) {
    const PixelBox picture{360, 0, 480, 360};
    // The picture's first and last framebuffer pixels, at full resolution.
    EXPECT_EQ(under(360.0, 0.0, picture, 480, 360), std::pair(0, 0));
    EXPECT_EQ(under(839.9, 359.9, picture, 480, 360), std::pair(479, 359));
    EXPECT_EQ(under(750.5, 200.5, picture, 480, 360), std::pair(390, 200));
    // Just outside: over the panel, past the right or bottom edge, above the top.
    EXPECT_FALSE(under(359.9, 10.0, picture, 480, 360));
    EXPECT_FALSE(under(840.0, 10.0, picture, 480, 360));
    EXPECT_FALSE(under(400.0, 360.0, picture, 480, 360));
    EXPECT_FALSE(under(400.0, -0.5, picture, 480, 360));
    // At half resolution a picture pixel is two framebuffer pixels wide.
    EXPECT_EQ(under(361.9, 1.9, picture, 240, 180), std::pair(0, 0));
    EXPECT_EQ(under(362.0, 2.0, picture, 240, 180), std::pair(1, 1));
    EXPECT_EQ(under(839.0, 359.0, picture, 240, 180), std::pair(239, 179));
    EXPECT_FALSE(under(400.0, 10.0, PixelBox{}, 480, 360));
    EXPECT_FALSE(under(400.0, 10.0, picture, 0, 360));
}

TEST(ViewLayout, PicturePixelsMapBackToTheFramebufferPixelsThatShowThem) {
    const PixelBox picture{360, 0, 480, 360};
    EXPECT_EQ(pictureToFramebuffer(picture, 480, 360, 0, 0, 0, 0), (PixelBox{360, 0, 1, 1}));
    EXPECT_EQ(pictureToFramebuffer(picture, 480, 360, 479, 359, 479, 359),
              (PixelBox{839, 359, 1, 1}));
    // Corners in either order; half resolution doubles the sides.
    EXPECT_EQ(pictureToFramebuffer(picture, 240, 180, 9, 5, 2, 1), (PixelBox{364, 2, 16, 10}));
    // Every framebuffer pixel of the box maps back to the picture's pixel, also when a picture
    // pixel is not a whole number of framebuffer pixels (0.3 of the width).
    for (const int renderWidth : {240, 144}) {
        for (int p = 0; p < renderWidth; ++p) {
            const PixelBox box =
                pictureToFramebuffer(picture, renderWidth, 180, p, p / 2, p, p / 2);
            for (int x = box.x; x < box.x + box.width; ++x) {
                EXPECT_EQ(under(x + 0.5, box.y + 0.5, picture, renderWidth, 180),
                          std::pair(p, p / 2));
            }
            // The framebuffer pixels beside the box show other pixels.
            EXPECT_NE(under(box.x - 0.5, box.y + 0.5, picture, renderWidth, 180),
                      std::pair(p, p / 2));
            EXPECT_NE(under(box.x + box.width + 0.5, box.y + 0.5, picture, renderWidth, 180),
                      std::pair(p, p / 2));
        }
    }
}

TEST(ViewLayout, GlBoxesCountRowsFromTheBottom) {
    EXPECT_EQ(glBox(PixelBox{360, 0, 480, 360}, 360), (GlBox{360, 0, 480, 360}));
    EXPECT_EQ(glBox(PixelBox{10, 20, 5, 30}, 100), (GlBox{10, 50, 5, 30}));
    EXPECT_EQ(intersect(PixelBox{350, 5, 20, 20}, PixelBox{360, 0, 480, 360}),
              (PixelBox{360, 5, 10, 20}));
    EXPECT_TRUE(intersect(PixelBox{0, 0, 10, 10}, PixelBox{360, 0, 480, 360}).empty());
}

TEST(ViewLayout, TheUiScaleIsTheContentScalePerFramebufferScale) {
    EXPECT_FLOAT_EQ(uiScaleFor(1.0f, 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(uiScaleFor(2.0f, 1.0f), 2.0f); // X11, Windows: a 200 % monitor
    EXPECT_FLOAT_EQ(uiScaleFor(2.0f, 2.0f), 1.0f); // macOS Retina: ImGui counts points
    EXPECT_FLOAT_EQ(uiScaleFor(1.5f, 1.0f), 1.5f);
    EXPECT_FLOAT_EQ(uiScaleFor(9.0f, 1.0f), kMaxUiScale);
    EXPECT_FLOAT_EQ(uiScaleFor(0.1f, 1.0f), kMinUiScale);
    EXPECT_FLOAT_EQ(uiScaleFor(std::numeric_limits<float>::quiet_NaN(), 1.0f), 1.0f);
    EXPECT_FLOAT_EQ(uiScaleFor(1.0f, 0.0f), 1.0f);
    EXPECT_EQ(scaledPixels(kPanelColumnWidth, 1.0f, 1.0f), 360);
    EXPECT_EQ(scaledPixels(kPanelColumnWidth, 2.0f, 1.0f), 720);
    EXPECT_EQ(scaledPixels(kPanelColumnWidth, 1.0f, 2.0f), 720);
    EXPECT_EQ(scaledPixels(kPanelColumnWidth, 1.25f, 1.0f), 450);
}

} // namespace
} // namespace raylab::viewer
