// The views of one term: beauty = albedo * (direct + indirect) for the lab integrator, the
// visibility is 0 exactly where the shadow test says so, and the other views are what they say.

#include "core/bvh/bvh.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/integrators/pixel_inspection.h"
#include "core/integrators/term_views.h"
#include "core/render/renderer.h"

#include <cstring>
#include <gtest/gtest.h>

namespace raylab {
namespace {

class TermViews : public testing::Test {
protected:
    Scene scene = makeCornellBox();
    Bvh bvh = buildBvh(scene);
    RenderSettings settings;

    TermViews() {
        settings.width = 120;
        settings.height = 90;
    }

    Framebuffer view(View v) const {
        RenderSettings s = settings;
        s.view = v;
        return render(scene, bvh, s);
    }
};

TEST_F(TermViews, BeautyIsAlbedoTimesDirectPlusIndirectForTheLabIntegrator) {
    for (float epsilon : {1e-3f, 0.0f}) {
        settings.shadowEpsilon = epsilon;
        const Framebuffer beauty = view(View::Beauty);
        const Framebuffer albedo = view(View::Albedo);
        const Framebuffer direct = view(View::Direct);
        const Framebuffer indirect = view(View::Indirect);
        int shadowed = 0;
        for (std::size_t i = 0; i < beauty.pixels.size(); ++i) {
            // The same float operations as the lab's R = rho * (D + N): equal bits.
            ASSERT_EQ(beauty.pixels[i], albedo.pixels[i] * (direct.pixels[i] + indirect.pixels[i]))
                << "pixel " << i << ", epsilon " << epsilon;
            shadowed += direct.pixels[i] == glm::vec3(0.0f) ? 1 : 0;
        }
        EXPECT_GT(shadowed, 100); // shadows (and with epsilon 0, acne) are in the direct view
    }
}

TEST_F(TermViews, VisibilityIsZeroExactlyWhereTheShadowTestSaysSo) {
    const Framebuffer visibility = view(View::Visibility);
    int dark = 0;
    for (int y = 0; y < settings.height; ++y) {
        for (int x = 0; x < settings.width; ++x) {
            const PixelInspection p = inspectPixel(scene, bvh, EmitterTable(), settings, x, y);
            const bool seesLight = p.hit && p.cosTheta > 0.0f && !p.shadowed;
            ASSERT_EQ(visibility.at(x, y), glm::vec3(seesLight ? 1.0f : 0.0f)) << x << ", " << y;
            dark += seesLight ? 0 : 1;
        }
    }
    EXPECT_GT(dark, 100);
}

TEST_F(TermViews, ASphereLightsVisibilityIsFractionalInThePenumbra) {
    settings.light.radius = 0.25f;
    settings.samplesPerPixel = 64;
    const Framebuffer visibility = view(View::Visibility);
    int between = 0;
    for (const glm::vec3& v : visibility.pixels) {
        ASSERT_GE(v.x, 0.0f);
        ASSERT_LE(v.x, 1.0f);
        between += v.x > 0.1f && v.x < 0.9f ? 1 : 0;
    }
    EXPECT_GT(between, 20);
}

TEST_F(TermViews, AlbedoNormalAndDepthAreWhatTheySay) {
    const Framebuffer albedo = view(View::Albedo);
    const Framebuffer normal = view(View::Normal);
    const Framebuffer depth = view(View::Depth);
    for (int y = 0; y < settings.height; y += 7) {
        for (int x = 0; x < settings.width; x += 7) {
            const PixelInspection p = inspectPixel(scene, bvh, EmitterTable(), settings, x, y);
            if (!p.hit) {
                continue;
            }
            EXPECT_EQ(albedo.at(x, y), p.rho);
            EXPECT_EQ(normal.at(x, y), p.normal * 0.5f + glm::vec3(0.5f));
            EXPECT_EQ(depth.at(x, y), glm::vec3(p.t));
        }
    }
}

TEST_F(TermViews, ThePathIntegratorsIndirectViewIsItsN) {
    // The indirect view's samples are the N estimates the beauty pass keeps in its film's
    // indirect layer: the same estimator with the same random numbers, pixel by pixel.
    settings.integrator = Integrator::Path;
    settings.samplesPerPixel = 8;
    Film film(settings.width, settings.height, filmLayersFor(settings));
    for (int i = 0; i < settings.samplesPerPixel; ++i) {
        ASSERT_TRUE(renderPass(scene, bvh, settings, film));
    }
    const Framebuffer indirect = view(View::Indirect);
    double total = 0.0;
    for (std::size_t i = 0; i < indirect.pixels.size(); ++i) {
        const glm::vec3 sum = glm::vec3(film.indirect()[i]);
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(indirect.pixels[i][c] * 8.0f, sum[c], 1e-5f * (1.0f + sum[c])) << i;
        }
        total += sum.x;
    }
    EXPECT_GT(total, 0.0);
}

TEST_F(TermViews, CostIsTheHeatOfTheCountedTraversals) {
    EXPECT_EQ(costHeat(0.0f), 0.0f);
    EXPECT_EQ(costHeat(kCostHeatMax), 1.0f);
    EXPECT_EQ(costHeat(1e6f), 1.0f);
    EXPECT_LT(costHeat(10.0f), costHeat(100.0f));
    EXPECT_EQ(heatColor(0.0f), glm::vec3(0.0f));
    EXPECT_EQ(heatColor(1.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(heatColor(0.6f), glm::vec3(0.0f, 1.0f, 0.0f));
    const Framebuffer cost = view(View::Cost);
    int checked = 0;
    for (int y = 0; y < settings.height; y += 9) {
        for (int x = 0; x < settings.width; x += 9) {
            const PixelInspection p = inspectPixel(scene, bvh, EmitterTable(), settings, x, y);
            const float ops = static_cast<float>(p.cameraCost.nodes + p.cameraCost.triangles +
                                                 p.shadowCost.nodes + p.shadowCost.triangles);
            ASSERT_EQ(cost.at(x, y), heatColor(costHeat(ops))) << x << ", " << y;
            EXPECT_GE(p.cameraCost.nodes, 1u);
            checked += p.hit ? 1 : 0;
        }
    }
    EXPECT_GT(checked, 50);
}

TEST(TraversalCost, CountedQueriesGiveTheSameAnswersAndCountWhatTheyVisit) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    BvhBuildOptions scalarOnly;
    scalarOnly.simd = false;
    const Bvh binary = buildBvh(scene, scalarOnly);
    const PrimaryRays rays(Camera(), 64, 64);
    for (const Bvh* b : {&bvh, &binary}) {
        for (int i = 0; i < 64 * 64; i += 37) {
            const Ray ray =
                rays.through(static_cast<float>(i % 64) + 0.5f, static_cast<float>(i / 64) + 0.5f);
            TraversalCost cost;
            const Hit counted = closestHitCounted(*b, ray, cost);
            const Hit plain = closestHit(*b, ray);
            ASSERT_EQ(counted.triangle, plain.triangle);
            ASSERT_EQ(counted.t, plain.t);
            EXPECT_GE(cost.nodes, 1u);
            EXPECT_GE(cost.triangles, 1u);
            if (b == &bvh && !bvh.wideNodes.empty()) {
                EXPECT_EQ(cost.triangles % 8, 0u); // whole SIMD blocks
            }
            TraversalCost shadow;
            Ray up = ray;
            up.tMax = counted.t * 0.5f;
            EXPECT_EQ(anyHitCounted(*b, up, shadow), anyHit(*b, up));
        }
    }
}

} // namespace
} // namespace raylab
