// The path integrator and the lights beyond the lab, against closed forms (DESIGN.md section 5).
// Noisy results are checked statistically: fixed seeds, and tolerances of a few standard errors
// of the estimate, measured from the film's per-pixel second moments.

#include "core/bvh/bvh.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/integrators/path_integrator.h"
#include "core/lights/emitters.h"
#include "core/render/film.h"
#include "core/render/image_error.h"
#include "core/render/renderer.h"
#include "test_meshes.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace raylab {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The per-pixel mean and standard error of the mean of channel c of a film with moments.
struct PixelEstimate {
    double mean = 0.0;
    double standardError = 0.0;
};

PixelEstimate estimate(const Film& film, std::size_t pixel, int c) {
    const double n = film.samples();
    const double sum = fromFixed(film.sumOf(pixel).channel[c]);
    const double variance = std::max(0.0, (film.squares()[pixel][c] - sum * sum / n) / (n - 1.0));
    return {sum / n, std::sqrt(variance / n)};
}

Film renderFilm(const Scene& scene, const Bvh& bvh, const RenderSettings& s) {
    Film film(s.width, s.height, FilmLayers{true, true});
    for (int i = 0; i < s.samplesPerPixel; ++i) {
        EXPECT_TRUE(renderPass(scene, bvh, s, film));
    }
    return film;
}

// Inside a closed sphere of radius 1 and albedo a, the lab's point light of power 4 pi at the
// centre: D = P / (4 pi r^2) = 1 at every point.
struct Furnace {
    Scene scene;
    Bvh bvh;
    RenderSettings settings;

    explicit Furnace(float albedo) {
        scene = test::makePerturbedSphere(96, 192, 1.0f, 0.0f, 1);
        for (Material& m : scene.materials) {
            m.diffuse = glm::vec3(albedo);
        }
        bvh = buildBvh(scene);
        settings.integrator = Integrator::Path;
        settings.camera.position = {0.0f, 0.1f, -0.2f};
        settings.camera.pitchDegrees = -10.0f;
        settings.camera.verticalFovDegrees = 120.0f;
        settings.light.position = glm::vec3(0.0f);
        settings.light.intensity = static_cast<float>(4.0 * kPi);
        settings.shadowEpsilon = 1e-4f;
        settings.width = 6;
        settings.height = 6;
        settings.threads = 2;
    }
};

// Every pixel's R, per channel, within `relative` of `expected` and within 4 standard errors
// plus the tessellation's bias (the sphere's faces lie up to 0.05% inside the unit sphere).
void expectEveryPixelNear(const Film& film, double expected, double relative) {
    for (std::size_t p = 0; p < film.pixelCount(); ++p) {
        for (int c = 0; c < 3; ++c) {
            const PixelEstimate e = estimate(film, p, c);
            ASSERT_NEAR(e.mean, expected, relative * expected) << "pixel " << p;
            ASSERT_NEAR(e.mean, expected, 4.0 * e.standardError + 2e-3 * expected)
                << "pixel " << p << ", standard error " << e.standardError;
        }
    }
}

TEST(PathIntegrator, FurnaceConvergesToTheGeometricSeries) {
    // R = a D / (1 - a) with every bounce: here a = 0.5, so R = D = 1.
    Furnace furnace(0.5f);
    furnace.settings.maxBounces = kMaxBounces;
    furnace.settings.samplesPerPixel = 4096;
    const Film film = renderFilm(furnace.scene, furnace.bvh, furnace.settings);
    expectEveryPixelNear(film, 1.0, 0.01);
    // The estimate is noisy (Russian roulette): the test is not trivially exact.
    EXPECT_GT(estimate(film, 0, 0).standardError, 1e-4);
}

TEST(PathIntegrator, FurnaceWithKBouncesIsTheSeriesCutAfterKTerms) {
    // a D (1 - a^(k+1)) / (1 - a); up to 3 bounces no roulette, so the estimate is exact but for
    // the tessellation.
    for (float albedo : {0.5f, 0.8f}) {
        Furnace furnace(albedo);
        for (int k : {0, 1, 3, 6}) {
            furnace.settings.maxBounces = k;
            furnace.settings.samplesPerPixel = k > 3 ? 2048 : 16;
            const Film film = renderFilm(furnace.scene, furnace.bvh, furnace.settings);
            const double a = albedo;
            const double expected = a * (1.0 - std::pow(a, k + 1)) / (1.0 - a);
            SCOPED_TRACE(testing::Message() << "albedo " << albedo << ", " << k << " bounces");
            expectEveryPixelNear(film, expected, 0.01);
        }
    }
}

TEST(PathIntegrator, NoIndirectMeansDirectLightOnly) {
    Furnace furnace(0.5f);
    furnace.settings.indirect = false;
    furnace.settings.samplesPerPixel = 4;
    const Film film = renderFilm(furnace.scene, furnace.bvh, furnace.settings);
    expectEveryPixelNear(film, 0.5, 0.005); // rho D
    EXPECT_EQ(film.meanIndirect(), glm::vec3(0.0f));
}

TEST(PathIntegrator, TheMeanIndirectTermIsTheFurnacesN) {
    // N = R(y) everywhere in the furnace: R = a (D + N) and R = a D / (1 - a) give N = R.
    Furnace furnace(0.5f);
    furnace.settings.maxBounces = kMaxBounces;
    furnace.settings.samplesPerPixel = 1024;
    const Film film = renderFilm(furnace.scene, furnace.bvh, furnace.settings);
    const glm::vec3 n = film.meanIndirect();
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(n[c], 1.0, 0.01);
    }
}

// A wall (rho 0.5) at z = 3 facing the camera at the origin, and the lab's light in front of it.
struct Wall {
    Scene scene = test::makeQuadScene(20.0f, 3.0f, glm::vec3(0.5f));
    Bvh bvh = buildBvh(scene);
    RenderSettings settings;

    Wall() {
        settings.camera.position = glm::vec3(0.0f);
        settings.light.position = {0.3f, 0.2f, 1.0f};
        settings.indirect = false;
        settings.width = 24;
        settings.height = 16;
        settings.threads = 2;
    }
};

TEST(SphereLight, AFullyVisibleSphereLightsLikeThePointLightAtItsCentre) {
    // A sphere of power P seen whole from a plane gives the point light's irradiance exactly
    // (in expectation): compare pixel by pixel within 4 standard errors.
    Wall wall;
    wall.settings.samplesPerPixel = 1;
    const Framebuffer point = render(wall.scene, wall.bvh, wall.settings);
    wall.settings.light.radius = 1.5f; // 0.5 short of the wall
    wall.settings.samplesPerPixel = 256;
    for (Integrator integrator : {Integrator::Lab, Integrator::Path}) {
        wall.settings.integrator = integrator;
        wall.settings.maxBounces = 0;
        // The same pixel positions as the point light's single centred sample: one sample of
        // the path integrator's pixel is jittered, so compare against the pixel's mean instead.
        Film film = renderFilm(wall.scene, wall.bvh, wall.settings);
        RenderSettings pointMany = wall.settings;
        pointMany.light.radius = 0.0f;
        const Film pointFilm = renderFilm(wall.scene, wall.bvh, pointMany);
        double sumDifference = 0.0;
        double sumValue = 0.0;
        for (std::size_t p = 0; p < film.pixelCount(); ++p) {
            for (int c = 0; c < 3; ++c) {
                const PixelEstimate sphere = estimate(film, p, c);
                const PixelEstimate pointLight = estimate(pointFilm, p, c);
                ASSERT_NEAR(sphere.mean, pointLight.mean,
                            4.0 * std::hypot(sphere.standardError, pointLight.standardError) + 1e-6)
                    << "pixel " << p;
                sumDifference += sphere.mean - pointLight.mean;
                sumValue += pointLight.mean;
            }
        }
        EXPECT_LT(std::abs(sumDifference) / sumValue, 2e-3);
        EXPECT_GT(point.pixels[0].x, 0.0f);
    }
}

TEST(SphereLight, RadiusToZeroConvergesToThePointLightsImage) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.width = 96;
    s.height = 96;
    s.samplesPerPixel = 4;
    const Framebuffer point = render(scene, bvh, s);
    double previous = 1.0;
    for (float radius : {0.1f, 0.01f, 1e-4f}) {
        s.light.radius = radius;
        const double error = relativeRmse(render(scene, bvh, s), point);
        EXPECT_LT(error, previous) << radius;
        previous = error;
    }
    EXPECT_LT(previous, 2e-3);
}

TEST(SphereLight, ALargerSphereSoftensTheShadows) {
    // The lab's box: with radius 0 every pixel is either lit or in shadow; a sphere of radius 0.2
    // gives penumbra pixels between, which the point light's picture does not have.
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.width = 64;
    s.height = 64;
    s.samplesPerPixel = 64;
    s.indirect = false;
    s.light.radius = 0.2f;
    const Framebuffer soft = render(scene, bvh, s);
    s.light.radius = 0.0f;
    const Framebuffer hard = render(scene, bvh, s);
    const double error = relativeRmse(soft, hard);
    EXPECT_GT(error, 0.02);
    EXPECT_LT(error, 0.5);
}

// A wall lit by an emitting square between it and the camera (its front faces the wall, so the
// camera sees its dark back). One bounce, so every strategy estimates the same light.
struct EmitterScene {
    Scene scene;
    Bvh bvh;
    EmitterTable emitters;
    RenderSettings settings;

    EmitterScene() {
        scene.materials.push_back({"wall", glm::vec3(0.5f), glm::vec3(0.0f)});
        scene.materials.push_back({"light", glm::vec3(0.0f), glm::vec3(2.0f, 1.5f, 1.0f)});
        test::addSquareZ(scene, {0.0f, 0.0f, 3.0f}, 3.0f, 0);
        test::addSquareZ(scene, {0.4f, 0.3f, 2.5f}, 0.35f, 1);
        bvh = buildBvh(scene);
        emitters = buildEmitterTable(scene);
        settings.integrator = Integrator::Path;
        settings.camera.position = glm::vec3(0.0f);
        settings.light.intensity = 0.0f; // lit by its emitter alone
        settings.maxBounces = 1;
        settings.width = 16;
        settings.height = 12;
    }

    // Per-pixel means and variances of `samples` paths with `strategy`.
    std::vector<PixelEstimate> trace(EmitterStrategy strategy, int samples) const {
        const PrimaryRays rays(settings.camera, settings.width, settings.height);
        std::vector<PixelEstimate> result;
        for (int y = 0; y < settings.height; ++y) {
            for (int x = 0; x < settings.width; ++x) {
                const uint32_t pixel = static_cast<uint32_t>(y * settings.width + x);
                double sum = 0.0;
                double squares = 0.0;
                for (int i = 0; i < samples; ++i) {
                    const PixelSampler sampler(SamplerKind::Independent, pixel,
                                               static_cast<uint32_t>(i));
                    RayCounts counts;
                    // The pixel centre: every strategy sees the same point, only light varies.
                    const Ray ray =
                        rays.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                    const double v =
                        tracePath(scene, bvh, emitters, settings, ray, sampler, counts, strategy)
                            .radiance.x;
                    sum += v;
                    squares += v * v;
                }
                const double mean = sum / samples;
                const double variance = std::max(0.0, squares / samples - mean * mean);
                result.push_back({mean, std::sqrt(variance / samples)});
            }
        }
        return result;
    }
};

double totalVariance(const std::vector<PixelEstimate>& e) {
    double v = 0.0;
    for (const PixelEstimate& p : e) {
        v += p.standardError * p.standardError;
    }
    return v;
}

TEST(Emitters, LightSamplingBounceHitsAndMisAgreeAndMisHasTheLeastVariance) {
    const EmitterScene s;
    ASSERT_EQ(s.emitters.triangles.size(), 2u);
    const int samples = 2048;
    const auto light = s.trace(EmitterStrategy::LightSamplingOnly, samples);
    const auto bounce = s.trace(EmitterStrategy::BounceOnly, samples);
    const auto mis = s.trace(EmitterStrategy::Mis, samples);
    // A bounce that hits the emitter adds c = rho pi Le (channel x) and nothing otherwise: with
    // mean m its variance is m (c - m). Where few of the samples hit, the measured spread
    // underestimates that, so the bounce estimator's standard error is taken as at least the one
    // that its mean (from light sampling, which sees the emitter every time) implies.
    const double hitValue = 0.5 * kPi * 2.0;
    const auto bounceError = [&](std::size_t p) {
        const double m = std::clamp(light[p].mean, 0.0, hitValue);
        return std::max(bounce[p].standardError, std::sqrt(m * (hitValue - m) / samples));
    };
    double litPixels = 0;
    for (std::size_t p = 0; p < mis.size(); ++p) {
        ASSERT_NEAR(light[p].mean, bounce[p].mean,
                    4.5 * std::hypot(light[p].standardError, bounceError(p)) + 1e-6)
            << "pixel " << p;
        ASSERT_NEAR(mis[p].mean, light[p].mean,
                    4.5 * std::hypot(mis[p].standardError, light[p].standardError) + 1e-6)
            << "pixel " << p;
        ASSERT_NEAR(mis[p].mean, bounce[p].mean,
                    4.5 * std::hypot(mis[p].standardError, bounceError(p)) + 1e-6)
            << "pixel " << p;
        litPixels += mis[p].mean > 0.01 ? 1 : 0;
    }
    EXPECT_GT(litPixels, 0.6 * static_cast<double>(mis.size()));
    EXPECT_LT(totalVariance(mis), totalVariance(bounce));
    EXPECT_LT(totalVariance(mis), totalVariance(light));
}

TEST(Emitters, TheCameraSeesAnEmittersFrontAsPiLeAndItsBackAsDark) {
    EmitterScene s;
    // The camera between the emitter and the wall, facing the emitter's front.
    s.settings.camera.position = {0.4f, 0.3f, 2.9f};
    s.settings.camera.yawDegrees = 180.0f; // looking along -z, at the emitter's front
    s.settings.camera.verticalFovDegrees = 10.0f;
    s.settings.maxBounces = 0;
    const PrimaryRays rays(s.settings.camera, s.settings.width, s.settings.height);
    RayCounts counts;
    const PixelSampler sampler(SamplerKind::Sobol, 0, 0);
    const PathSample front = tracePath(s.scene, s.bvh, s.emitters, s.settings,
                                       rays.through(8.0f, 6.0f), sampler, counts);
    ASSERT_TRUE(front.hit);
    EXPECT_NEAR(front.radiance.x, kPi * 2.0, 1e-4);
    EXPECT_NEAR(front.radiance.y, kPi * 1.5, 1e-4);
    EXPECT_NEAR(front.radiance.z, kPi * 1.0, 1e-4);
}

// The lab's box with an emitting square (a lamp of Le 4) under its ceiling.
Scene cornellBoxWithLamp() {
    Scene scene = makeCornellBox();
    scene.materials.push_back({"lamp", glm::vec3(0.5f), glm::vec3(4.0f)});
    test::addSquareZ(scene, {0.0f, 0.5f, 0.5f}, 0.2f,
                     static_cast<uint32_t>(scene.materials.size() - 1));
    return scene;
}

TEST(PathIntegrator, SameBytesOnAnyThreadCountAndRepeatable) {
    const Scene scene = cornellBoxWithLamp();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.integrator = Integrator::Path;
    s.light.radius = 0.1f;
    s.width = 61;
    s.height = 37;
    s.samplesPerPixel = 3;
    s.threads = 1;
    const Framebuffer one = render(scene, bvh, s);
    for (int threads : {2, 5}) {
        s.threads = threads;
        const Framebuffer many = render(scene, bvh, s);
        ASSERT_EQ(0, std::memcmp(one.pixels.data(), many.pixels.data(),
                                 one.pixels.size() * sizeof(glm::vec3)))
            << threads << " threads";
    }
    s.sampler = SamplerKind::Independent;
    const Framebuffer independent = render(scene, bvh, s);
    EXPECT_NE(0, std::memcmp(one.pixels.data(), independent.pixels.data(),
                             one.pixels.size() * sizeof(glm::vec3)));
}

// tracePaths (a tile's paths a bounce at a time, the renderer's) against tracePath one by one:
// the same radiance, N and hit bit for bit, and the same ray counts, with emitters, a sphere
// light, Russian roulette (many bounces) and each switch of the lab.
TEST(PathIntegrator, PathsTracedTogetherEqualPathsTracedAlone) {
    const Scene scene = cornellBoxWithLamp();
    const Bvh bvh = buildBvh(scene);
    const EmitterTable emitters = buildEmitterTable(scene);
    RenderSettings base;
    base.integrator = Integrator::Path;
    base.light.radius = 0.1f;
    base.maxBounces = 12;
    base.width = 24;
    base.height = 20;
    RenderSettings noIndirect = base, noShadows = base, oneBounce = base;
    noIndirect.indirect = false;
    noShadows.shadows = false;
    oneBounce.maxBounces = 1;
    for (const RenderSettings& s : {base, noIndirect, noShadows, oneBounce}) {
        const PrimaryRays camera(s.camera, s.width, s.height);
        std::vector<Ray> rays;
        std::vector<PixelSampler> samplers;
        for (uint32_t sample = 0; sample < 3; ++sample) {
            for (int y = 0; y < s.height; ++y) {
                for (int x = 0; x < s.width; ++x) {
                    const PixelSampler sampler(s.sampler, static_cast<uint32_t>(y * s.width + x),
                                               sample);
                    const glm::vec2 offset = sampler.get2D(0);
                    rays.push_back(camera.through(static_cast<float>(x) + offset.x,
                                                  static_cast<float>(y) + offset.y));
                    samplers.push_back(sampler);
                }
            }
        }
        RayCounts alone, together;
        std::vector<PathSample> samples(rays.size());
        PathBatch batch;
        tracePaths(scene, bvh, emitters, s, rays, samplers, samples, together, batch);
        int hits = 0, bounced = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const PathSample one = tracePath(scene, bvh, emitters, s, rays[i], samplers[i], alone);
            ASSERT_EQ(one.hit, samples[i].hit) << i;
            ASSERT_EQ(0, std::memcmp(&one.radiance, &samples[i].radiance, sizeof(glm::vec3))) << i;
            ASSERT_EQ(0, std::memcmp(&one.indirect, &samples[i].indirect, sizeof(glm::vec3))) << i;
            hits += one.hit ? 1 : 0;
            bounced += one.indirect != glm::vec3(0.0f) ? 1 : 0;
        }
        EXPECT_EQ(alone.primary, together.primary);
        EXPECT_EQ(alone.shadow, together.shadow);
        EXPECT_EQ(alone.bounce, together.bounce);
        EXPECT_EQ(alone.primary, rays.size());
        EXPECT_GT(hits, static_cast<int>(rays.size()) / 2);
        if (s.indirect) {
            EXPECT_GT(bounced, hits / 2);
            if (s.maxBounces == 1) { // one bounce from every hit, no roulette before bounce 4
                EXPECT_EQ(alone.bounce, static_cast<uint64_t>(hits));
            } else {
                EXPECT_GT(alone.bounce, alone.primary);
            }
        } else {
            EXPECT_EQ(bounced, 0);
            EXPECT_EQ(alone.bounce, 0u);
        }
    }
}

TEST(PathIntegrator, CountsCameraShadowAndBounceRays) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.integrator = Integrator::Path;
    s.width = 20;
    s.height = 20;
    RayCounts counts;
    render(scene, bvh, s, &counts);
    EXPECT_EQ(counts.primary, 400u);
    EXPECT_GT(counts.bounce, 400u); // a closed box: most paths bounce several times
    EXPECT_GT(counts.shadow, counts.primary);
    EXPECT_EQ(counts.total(), counts.primary + counts.shadow + counts.bounce);
}

} // namespace
} // namespace raylab
