// The lab's steps: each preset renders what its name says.

#include "core/bvh/bvh.h"
#include "core/cornell_box.h"
#include "core/integrators/pixel_inspection.h"
#include "core/lab_presets.h"
#include "core/render/renderer.h"

#include <gtest/gtest.h>

namespace raylab {
namespace {

class LabPresets : public testing::Test {
protected:
    Scene scene = makeCornellBox();
    Bvh bvh = buildBvh(scene);

    static RenderSettings preset(const char* name) {
        const LabPreset* p = findLabPreset(name);
        EXPECT_NE(p, nullptr) << name;
        RenderSettings s;
        s.threads = 2;
        s.camera.position = {0.3f, 0.1f, -2.0f}; // a preset puts back the lab's camera
        s.samplesPerPixel = 9;
        if (p) {
            p->apply(s);
        }
        return s;
    }

    // Pixels whose centre ray hits the short (red) block's top.
    std::vector<std::pair<int, int>> redBlockTop(const RenderSettings& s) const {
        std::vector<std::pair<int, int>> pixels;
        for (int y = 0; y < s.height; y += 2) {
            for (int x = 0; x < s.width; x += 2) {
                const PixelInspection p = inspectPixel(scene, bvh, EmitterTable(), s, x, y);
                if (p.hit && p.material == static_cast<uint32_t>(LabColor::Red) &&
                    p.normal.y > 0.99f) {
                    pixels.push_back({x, y});
                }
            }
        }
        return pixels;
    }
};

TEST_F(LabPresets, SixStepsInTheLabsOrderOnTheLabsBox) {
    ASSERT_EQ(labPresets().size(), 6u);
    EXPECT_EQ(labPresets()[0].name, "lab-1-intersection");
    EXPECT_EQ(labPresets()[5].name, "lab-6-indirect");
    for (const LabPreset& p : labPresets()) {
        RenderSettings s = preset(std::string(p.name).c_str());
        EXPECT_EQ(s.camera, Camera()) << p.name;
        EXPECT_EQ(s.light, PointLight()) << p.name;
        EXPECT_EQ(s.width, 500);
        EXPECT_EQ(s.height, 500);
        EXPECT_EQ(s.samplesPerPixel, 1);
        EXPECT_EQ(s.threads, 2) << "a preset keeps the thread count";
        EXPECT_FALSE(p.shows.empty());
        EXPECT_FALSE(p.equation.empty());
    }
    EXPECT_EQ(findLabPreset("lab-7"), nullptr);
    EXPECT_EQ(preset("lab-6-indirect"), [] {
        RenderSettings lab;
        lab.threads = 2;
        return lab;
    }());
}

TEST_F(LabPresets, IntersectionShowsFlatColoursAndLightShowsDAlone) {
    const RenderSettings one = preset("lab-1-intersection");
    const Framebuffer flat = render(scene, bvh, one);
    const PixelInspection wall = inspectPixel(scene, bvh, EmitterTable(), one, 250, 150);
    EXPECT_EQ(flat.at(250, 150), wall.rho);
    const RenderSettings two = preset("lab-2-light");
    const Framebuffer light = render(scene, bvh, two);
    // No colour: D is the same in every channel; no shadows: D is the unshadowed one.
    for (const auto& [x, y] : redBlockTop(two)) {
        const glm::vec3 d = light.at(x, y);
        EXPECT_EQ(d.x, d.y);
        EXPECT_EQ(d.y, d.z);
    }
    int darkFloor = 0;
    for (int x = 0; x < 500; x += 5) {
        darkFloor += light.at(x, 480) == glm::vec3(0.0f) ? 1 : 0;
    }
    EXPECT_EQ(darkFloor, 0) << "lab-2 has no shadows on the floor";
}

TEST_F(LabPresets, AcneSpecklesTheBlockTopAndTheLabsEpsilonRemovesIt) {
    const RenderSettings four = preset("lab-4-acne");
    const RenderSettings five = preset("lab-5-shadows");
    const Framebuffer acne = render(scene, bvh, four);
    const Framebuffer clean = render(scene, bvh, five);
    const auto top = redBlockTop(four);
    ASSERT_GT(top.size(), 100u);
    int blackAcne = 0;
    int blackClean = 0;
    for (const auto& [x, y] : top) {
        blackAcne += acne.at(x, y) == glm::vec3(0.0f) ? 1 : 0;
        blackClean += clean.at(x, y) == glm::vec3(0.0f) ? 1 : 0;
    }
    EXPECT_GT(blackAcne, static_cast<int>(top.size()) / 10) << "lab-4: black speckles";
    EXPECT_EQ(blackClean, 0) << "lab-5: no speckles on the lit block top";
    // lab-5's shadows are black (no indirect light yet), lab-6's are not.
    const Framebuffer lit = render(scene, bvh, preset("lab-6-indirect"));
    int blackShadow = 0;
    int litShadow = 0;
    for (int x = 0; x < 500; x += 3) {
        for (int y = 400; y < 500; y += 3) {
            if (clean.at(x, y) == glm::vec3(0.0f)) {
                ++blackShadow;
                litShadow += lit.at(x, y).x > 0.0f ? 1 : 0;
            }
        }
    }
    EXPECT_GT(blackShadow, 50);
    EXPECT_EQ(litShadow, blackShadow);
}

} // namespace
} // namespace raylab
