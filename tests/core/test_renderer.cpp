// The renderer: determinism across thread counts, progressive accumulation, cancellation.

#include "core/bvh/bvh.h"
#include "core/cornell_box.h"
#include "core/render/display_transform.h"
#include "core/render/renderer.h"
#include "core/sampling/hash.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <utility>

namespace raylab {
namespace {

bool sameBits(const Framebuffer& a, const Framebuffer& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

TEST(Renderer, SameBitsWhateverTheThreadCount) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.width = 161; // not a multiple of the tile size
    s.height = 97;
    s.samplesPerPixel = 3;
    s.threads = 1;
    const Framebuffer reference = render(scene, bvh, s);
    for (int threads : {2, 3, 8}) {
        s.threads = threads;
        EXPECT_TRUE(sameBits(render(scene, bvh, s), reference)) << threads << " threads";
    }
}

// The display bytes a pass writes tile by tile are toRgba8 of the sums after that pass.
TEST(Renderer, DisplayBytesWrittenDuringThePassAreThoseOfTheSums) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    for (DisplayMode mode : {DisplayMode::Lab, DisplayMode::Srgb}) {
        RenderSettings s;
        s.width = 83; // partial tiles on both axes
        s.height = 45;
        s.display = mode;
        s.exposure = 0.5f;
        s.threads = 2;
        for (Integrator integrator : {Integrator::Lab, Integrator::Path}) {
            s.integrator = integrator;
            Film film(83, 45, filmLayersFor(s));
            std::vector<uint8_t> during(4 * film.pixelCount(), 7);
            std::vector<uint8_t> after(4 * film.pixelCount());
            for (uint32_t sample = 0; sample < 3; ++sample) {
                PassOptions options;
                options.displayRgba = during;
                ASSERT_TRUE(renderPass(scene, bvh, s, film, nullptr, options));
                ASSERT_EQ(film.samples(), sample + 1);
                toRgba8(film.mean().pixels, 1.0f, mode, s.exposure, after);
                ASSERT_EQ(during, after) << "sample " << sample;
                film.toDisplay(after, mode, s.exposure);
                ASSERT_EQ(during, after) << "sample " << sample;
            }
            EXPECT_GT(std::count(after.begin(), after.end(), 0), 0); // not a blank picture
            EXPECT_GT(std::count_if(after.begin(), after.end(), [](uint8_t v) { return v > 20; }),
                      1000);
        }
    }
}

TEST(Renderer, CountsOnePrimaryRayPerPixelPerSample) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.width = 40;
    s.height = 30;
    s.samplesPerPixel = 2;
    RayCounts counts;
    render(scene, bvh, s, &counts);
    EXPECT_EQ(counts.primary, 2u * 40u * 30u);
    EXPECT_GT(counts.shadow, 0u);
    EXPECT_LE(counts.shadow, counts.primary);
}

TEST(Renderer, OneSampleIsTheLabsCentredRayAndMoreSamplesAverageJitteredOnes) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.width = 64;
    s.height = 64;
    const Framebuffer one = render(scene, bvh, s);
    const PrimaryRays rays(s.camera, s.width, s.height);
    RayCounts counts;
    EXPECT_EQ(one.at(10, 20), shadeLab(scene, bvh, s, rays.through(10.5f, 20.5f), counts));

    // N samples = the sums of passes 0..N-1 times 1/N, which is what the viewer shows.
    s.samplesPerPixel = 4;
    const Framebuffer four = render(scene, bvh, s);
    Film film(64, 64);
    for (uint32_t pass = 0; pass < 4; ++pass) {
        ASSERT_TRUE(renderPass(scene, bvh, s, film));
    }
    EXPECT_TRUE(sameBits(film.mean(), four));
    // The mean is the average of the four one-sample pictures, to float rounding.
    Framebuffer each[4];
    for (uint32_t pass = 0; pass < 4; ++pass) {
        Film part(64, 64);
        part.startAt(pass);
        ASSERT_TRUE(renderPass(scene, bvh, s, part));
        each[pass] = part.mean();
    }
    for (std::size_t i = 0; i < film.pixelCount(); ++i) {
        const glm::vec3 average =
            (each[0].pixels[i] + each[1].pixels[i] + each[2].pixels[i] + each[3].pixels[i]) * 0.25f;
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(four.pixels[i][c], average[c], 1e-6f * std::max(1.0f, average[c]));
        }
    }
    EXPECT_FALSE(sameBits(one, four)) << "jittered samples must smooth the edges";

    // Sample 0 stores: sums left over from another picture (or garbage) need no clearing.
    Film stale(64, 64);
    PixelSum garbage;
    garbage.store(glm::vec3(1e30f, -7.0f, 3.0f));
    stale.assign(std::vector<PixelSum>(stale.pixelCount(), garbage), 0, 0);
    for (uint32_t pass = 0; pass < 4; ++pass) {
        ASSERT_TRUE(renderPass(scene, bvh, s, stale));
    }
    for (std::size_t i = 0; i < film.pixelCount(); ++i) {
        ASSERT_EQ(stale.sumOf(i), film.sumOf(i));
    }
}

TEST(Renderer, SampleOffsetsAreCentredFirstThenDistinctInsideThePixel) {
    const PixelOffset centre = samplePixelOffset(3, 4, 0);
    EXPECT_EQ(centre.dx, 0.5f);
    EXPECT_EQ(centre.dy, 0.5f);
    int repeats = 0;
    PixelOffset previous = centre;
    for (uint32_t i = 1; i < 1000; ++i) {
        const PixelOffset o = samplePixelOffset(17, 9, i);
        ASSERT_GE(o.dx, 0.0f);
        ASSERT_LT(o.dx, 1.0f);
        ASSERT_GE(o.dy, 0.0f);
        ASSERT_LT(o.dy, 1.0f);
        repeats += (o.dx == previous.dx && o.dy == previous.dy) ? 1 : 0;
        previous = o;
    }
    EXPECT_EQ(repeats, 0);
    // Neighbouring pixels do not share a pattern.
    EXPECT_NE(samplePixelOffset(17, 9, 1).dx, samplePixelOffset(18, 9, 1).dx);
}

TEST(Renderer, ACancelledPassStopsAndSaysSo) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    Film film(500, 500);
    ASSERT_TRUE(renderPass(scene, bvh, s, film));
    std::atomic<bool> cancel{true};
    PassOptions options;
    options.cancel = &cancel;
    EXPECT_FALSE(renderPass(scene, bvh, s, film, nullptr, options));
    // A cancelled pass restarts the film: its sums are worthless.
    EXPECT_EQ(film.samples(), 0u);
}

TEST(Renderer, ProgressRisesToOne) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.width = 100;
    s.height = 100;
    s.samplesPerPixel = 2;
    s.threads = 1;
    double last = 0.0;
    int calls = 0;
    PassOptions options;
    options.progress = [&](double f) {
        EXPECT_GE(f, last);
        last = f;
        ++calls;
    };
    render(scene, bvh, s, nullptr, options);
    EXPECT_GT(calls, 2);
    EXPECT_DOUBLE_EQ(last, 1.0);
}

} // namespace
} // namespace raylab
