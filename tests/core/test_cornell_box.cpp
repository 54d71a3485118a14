// The lab's box: its geometry, the colours where DESIGN.md puts them, shadows, and shadow acne.

#include "core/bvh/bvh.h"
#include "core/cornell_box.h"
#include "core/render/renderer.h"

#include <gtest/gtest.h>

namespace raylab {
namespace {

class CornellBox : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        scene_ = new Scene(makeCornellBox());
        bvh_ = new Bvh(buildBvh(*scene_));
    }
    static void TearDownTestSuite() {
        delete bvh_;
        delete scene_;
    }
    // The scene triangle the centre ray of pixel (x, y) hits under settings s.
    static Hit primaryHit(const RenderSettings& s, int x, int y) {
        const PrimaryRays rays(s.camera, s.width, s.height);
        return closestHit(*bvh_,
                          rays.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
    }
    static LabColor colorAt(const RenderSettings& s, int x, int y) {
        const Hit hit = primaryHit(s, x, y);
        EXPECT_TRUE(hit.found());
        return static_cast<LabColor>(scene_->triangles[hit.triangle].material);
    }
    // True when the pixel got no direct light: R == rho * N exactly.
    static bool inShadow(const Framebuffer& image, const RenderSettings& s, int x, int y) {
        const Hit hit = primaryHit(s, x, y);
        const glm::vec3 rho = scene_->materials[scene_->triangles[hit.triangle].material].diffuse;
        return image.at(x, y) == rho * s.indirect3();
    }
    static Scene* scene_;
    static Bvh* bvh_;
};
Scene* CornellBox::scene_ = nullptr;
Bvh* CornellBox::bvh_ = nullptr;

TEST_F(CornellBox, HasTheLabsThirtyTrianglesInsideTheUnitCube) {
    ASSERT_EQ(scene_->triangles.size(), 30u);
    const Aabb box = scene_->bounds();
    EXPECT_EQ(box.lower, glm::vec3(-1.0f));
    EXPECT_EQ(box.upper, glm::vec3(1.0f));
    // Order and colours: floor, left, right, ceiling, back wall, short block, tall block.
    const LabColor expected[] = {LabColor::Green, LabColor::Purple, LabColor::Yellow,
                                 LabColor::Cyan, LabColor::White};
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(scene_->triangles[i].material, static_cast<uint32_t>(expected[i / 2]));
    }
    for (int i = 10; i < 20; ++i) {
        EXPECT_EQ(scene_->triangles[i].material, static_cast<uint32_t>(LabColor::Red));
    }
    for (int i = 20; i < 30; ++i) {
        EXPECT_EQ(scene_->triangles[i].material, static_cast<uint32_t>(LabColor::Blue));
    }
    EXPECT_EQ(labColor(LabColor::Purple), glm::vec3(0.75f, 0.15f, 0.75f));
    // The short block's top is at 165 of 555: y = 165 * 2/555 - 1.
    EXPECT_FLOAT_EQ(scene_->triangles[18].v0.y, 165.0f * 2.0f / 555.0f - 1.0f);
    for (const Triangle& tri : scene_->triangles) {
        EXPECT_TRUE(isValidTriangle(tri));
    }
}

TEST_F(CornellBox, DefaultViewShowsEachWallWhereDesignSaysItIs) {
    const RenderSettings s;                            // the lab's defaults, 500 x 500
    EXPECT_EQ(colorAt(s, 250, 495), LabColor::Green);  // floor at the bottom
    EXPECT_EQ(colorAt(s, 250, 5), LabColor::Cyan);     // ceiling at the top
    EXPECT_EQ(colorAt(s, 5, 250), LabColor::Purple);   // left wall
    EXPECT_EQ(colorAt(s, 495, 250), LabColor::Yellow); // right wall
    EXPECT_EQ(colorAt(s, 250, 180), LabColor::White);  // back wall, above the blocks
    EXPECT_EQ(colorAt(s, 320, 360), LabColor::Red);    // short block: front right
    EXPECT_EQ(colorAt(s, 170, 250), LabColor::Blue);   // tall block: back left

    // The rendered colour at each is rho times one grey factor (white light and white N).
    const Framebuffer image = render(*scene_, *bvh_, s);
    for (const auto& [x, y] : {std::pair{250, 495},
                               {250, 5},
                               {5, 250},
                               {495, 250},
                               {250, 180},
                               {320, 360},
                               {170, 250}}) {
        const glm::vec3 rho = labColor(colorAt(s, x, y));
        const glm::vec3 ratio = image.at(x, y) / rho;
        EXPECT_GT(ratio.x, 0.0f);
        EXPECT_NEAR(ratio.x, ratio.y, 1e-5f * ratio.x);
        EXPECT_NEAR(ratio.x, ratio.z, 1e-5f * ratio.x);
    }
}

TEST_F(CornellBox, BothBlocksCastShadowsOnTheFloor) {
    RenderSettings s;
    const Framebuffer withShadows = render(*scene_, *bvh_, s);
    s.shadows = false;
    const Framebuffer without = render(*scene_, *bvh_, s);
    s.shadows = true;
    int shortBlockSide = 0, tallBlockSide = 0, shadowedWithout = 0;
    const PrimaryRays rays(s.camera, s.width, s.height);
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Hit hit = primaryHit(s, x, y);
            if (hit.triangle > 1) {
                continue; // not the floor
            }
            shadowedWithout += inShadow(without, s, x, y) ? 1 : 0;
            if (inShadow(withShadows, s, x, y)) {
                const Ray ray =
                    rays.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                const float worldX = ray.origin.x + hit.t * ray.direction.x;
                // The short block stands at negative x (image right), the tall one at positive.
                (worldX < 0.0f ? shortBlockSide : tallBlockSide) += 1;
            }
        }
    }
    EXPECT_EQ(shadowedWithout, 0);
    EXPECT_GT(shortBlockSide, 500);
    EXPECT_GT(tallBlockSide, 500);
}

TEST_F(CornellBox, EpsilonZeroShowsAcneOnTheBlockTopsAndTheDefaultDoesNot) {
    RenderSettings s;
    auto acneOnTops = [&](float epsilon, int& topPixels) {
        s.shadowEpsilon = epsilon;
        const Framebuffer image = render(*scene_, *bvh_, s);
        int dark = 0;
        topPixels = 0;
        for (int y = 0; y < s.height; ++y) {
            for (int x = 0; x < s.width; ++x) {
                const uint32_t t = primaryHit(s, x, y).triangle;
                if (t == 18 || t == 19 || t == 28 || t == 29) { // the blocks' tops
                    ++topPixels;
                    dark += inShadow(image, s, x, y) ? 1 : 0;
                }
            }
        }
        return dark;
    };
    int tops = 0;
    const int acne = acneOnTops(0.0f, tops);
    ASSERT_GT(tops, 1000);
    EXPECT_GT(acne, tops / 20) << "epsilon 0 should darken a speckle of the tops";
    EXPECT_LT(acne, tops) << "acne is a speckle, not a full shadow";
    EXPECT_EQ(acneOnTops(1e-3f, tops), 0);
}

} // namespace
} // namespace raylab
