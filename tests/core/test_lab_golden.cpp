// The lab integrator's pictures do not change: 64-bit FNV-1a hashes of render()'s floats for
// several settings, taken from PFM files written by raylab-render before the Film and the
// integrators existed (commit 625e83c). Each sample is still the same floats; what changed since
// is how samples add up: the film's sums are exact (render/exact_sum.h, so that renders split by
// sample ranges merge bit for bit). One- and two-sample pictures keep their bytes; from three
// samples on, the old float running sum is rebuilt here from the samples, one film per sample,
// and gives the old bytes, and render()'s exact means are within rounding of it.

#include "core/bvh/bvh.h"
#include "core/cornell_box.h"
#include "core/render/renderer.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>

namespace raylab {
namespace {

uint64_t fnv1a(const Framebuffer& image) {
    uint64_t hash = 0xcbf29ce484222325ULL;
    const auto* bytes = reinterpret_cast<const unsigned char*>(image.pixels.data());
    for (std::size_t i = 0; i < image.pixels.size() * sizeof(glm::vec3); ++i) {
        hash = (hash ^ bytes[i]) * 0x100000001b3ULL;
    }
    return hash;
}

// The picture as the film made it before its sums were exact: each sample's floats added in
// sample order in float, times 1 / n in float.
Framebuffer floatRunningSum(const Scene& scene, const Bvh& bvh, const RenderSettings& settings) {
    Framebuffer sum(settings.width, settings.height);
    for (int s = 0; s < settings.samplesPerPixel; ++s) {
        Film one(settings.width, settings.height);
        one.startAt(static_cast<uint32_t>(s));
        EXPECT_TRUE(renderPass(scene, bvh, settings, one));
        const Framebuffer sample = one.mean(); // one sample: its floats exactly
        for (std::size_t i = 0; i < sum.pixels.size(); ++i) {
            sum.pixels[i] = s == 0 ? sample.pixels[i] : sum.pixels[i] + sample.pixels[i];
        }
    }
    const float scale = 1.0f / static_cast<float>(settings.samplesPerPixel);
    for (glm::vec3& p : sum.pixels) {
        p *= scale;
    }
    return sum;
}

TEST(LabGolden, TheLabsPicturesAreTheSameBytesAsBeforeTheFilm) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    struct Case {
        const char* what;
        RenderSettings settings;
        uint64_t hash;
    };
    std::vector<Case> cases;
    RenderSettings s;
    cases.push_back({"the lab's defaults", s, 0xd9a9d4f9015be020ULL});
    s.samplesPerPixel = 4;
    cases.push_back({"4 samples", s, 0x7e6cad461579a66fULL});
    s.samplesPerPixel = 3;
    s.shadowEpsilon = 0.0f;
    cases.push_back({"3 samples, epsilon 0", s, 0x16e6347142d7c7fcULL});
    s = RenderSettings();
    s.shadows = false;
    s.samplesPerPixel = 2;
    s.width = 320;
    s.height = 200;
    cases.push_back({"no shadows, 2 samples, 320 x 200", s, 0x579aef8e464599ceULL});
    s = RenderSettings();
    s.indirect = false;
    s.samplesPerPixel = 5;
    cases.push_back({"no indirect, 5 samples", s, 0xc6fead127b2db2b4ULL});
    for (const Case& c : cases) {
        const Framebuffer exact = render(scene, bvh, c.settings);
        const Framebuffer floatSums = floatRunningSum(scene, bvh, c.settings);
        EXPECT_EQ(fnv1a(floatSums), c.hash) << c.what;
        if (c.settings.samplesPerPixel <= 2) {
            EXPECT_EQ(fnv1a(exact), c.hash) << c.what;
        }
        // The float running sum rounds once per sample: n - 1 roundings of at most half an ulp
        // of the sum, then one of the scaling, and the exact mean one.
        const float n = static_cast<float>(c.settings.samplesPerPixel);
        for (std::size_t i = 0; i < exact.pixels.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                const float bound = (n + 1.0f) * 0x1p-24f * std::fabs(floatSums.pixels[i][k]);
                ASSERT_LE(std::fabs(exact.pixels[i][k] - floatSums.pixels[i][k]), bound)
                    << c.what << ", pixel " << i;
            }
        }
    }
    // A light radius of 0 is the lab's point light: the same bytes.
    RenderSettings radiusZero;
    radiusZero.light.radius = 0.0f;
    EXPECT_EQ(fnv1a(render(scene, bvh, radiusZero)), cases[0].hash);
}

} // namespace
} // namespace raylab
