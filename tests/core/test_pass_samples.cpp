// Passes of several samples (PassOptions::samples): a tile takes all of a pass's samples in turn,
// and the film ends up with the same bits (sums, moments, the indirect layer, display bytes) as
// one sample a pass, for both integrators, from an empty film or the middle of a range, on the
// whole image or a crop.

#include "core/bvh/bvh.h"
#include "core/cornell_box.h"
#include "core/render/renderer.h"

#include <cstring>
#include <gtest/gtest.h>
#include <vector>

namespace raylab {
namespace {

struct Rendered {
    Film film;
    std::vector<uint8_t> display;
};

// Samples [first, end) of `window` in passes of the given sizes (one pass a size, in order).
Rendered renderInPasses(const Scene& scene, const Bvh& bvh, const RenderSettings& s,
                        FilmWindow window, uint32_t first, const std::vector<uint32_t>& passes) {
    Rendered r;
    r.film.reset(window, FilmLayers{true, s.integrator == Integrator::Path});
    r.film.startAt(first);
    r.display.assign(4 * r.film.pixelCount(), 0);
    for (const uint32_t samples : passes) {
        PassOptions options;
        options.samples = samples;
        options.displayRgba = r.display;
        EXPECT_TRUE(renderPass(scene, bvh, s, r.film, nullptr, options));
    }
    return r;
}

void expectSameFilm(const Rendered& a, const Rendered& b) {
    ASSERT_EQ(a.film.pixelCount(), b.film.pixelCount());
    EXPECT_EQ(a.film.firstSample(), b.film.firstSample());
    EXPECT_EQ(a.film.nextSample(), b.film.nextSample());
    int differing = 0;
    for (std::size_t i = 0; i < a.film.pixelCount(); ++i) {
        differing += a.film.sumOf(i) == b.film.sumOf(i) ? 0 : 1;
        // Moments and N are floats added in sample order per pixel: the same order either way.
        differing += std::memcmp(&a.film.squares()[i], &b.film.squares()[i], 12) == 0 ? 0 : 1;
        if (!a.film.indirect().empty()) {
            differing += std::memcmp(&a.film.indirect()[i], &b.film.indirect()[i], 16) == 0 ? 0 : 1;
        }
    }
    EXPECT_EQ(differing, 0);
    // The display bytes written as each pass ends are those of the whole film.
    EXPECT_EQ(a.display, b.display);
    std::vector<uint8_t> after(a.display.size());
    b.film.toDisplay(after, DisplayMode::Lab, 0.0f);
    EXPECT_EQ(after, b.display);
}

class PassSamples : public ::testing::Test {
protected:
    Scene scene_ = makeCornellBox();
    Bvh bvh_ = buildBvh(scene_);
};

TEST_F(PassSamples, SeveralSamplesAPassAreOneSampleAPassBitForBit) {
    for (Integrator integrator : {Integrator::Lab, Integrator::Path}) {
        for (float lightRadius : {0.0f, 0.1f}) { // the lab's packets, and its sampled pass
            RenderSettings s;
            s.width = 45;
            s.height = 31;
            s.integrator = integrator;
            s.light.radius = lightRadius;
            const FilmWindow whole{0, 0, s.width, s.height};
            // From an empty film: the first, second and later samples' writes in one pass.
            const Rendered single =
                renderInPasses(scene_, bvh_, s, whole, 0, std::vector<uint32_t>(7, 1));
            const Rendered grouped = renderInPasses(scene_, bvh_, s, whole, 0, {3, 4});
            const Rendered one = renderInPasses(scene_, bvh_, s, whole, 0, {7});
            SCOPED_TRACE(integrator == Integrator::Lab ? "lab" : "path");
            expectSameFilm(single, grouped);
            expectSameFilm(single, one);
        }
    }
}

TEST_F(PassSamples, ARangeInTheMiddleOnACropIsTheSameToo) {
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    const FilmWindow crop{9, 5, 50, 40};
    const Rendered single = renderInPasses(scene_, bvh_, s, crop, 5, {1, 1, 1, 1, 1});
    const Rendered grouped = renderInPasses(scene_, bvh_, s, crop, 5, {2, 3});
    expectSameFilm(single, grouped);
    EXPECT_EQ(grouped.film.samples(), 5u);
}

TEST_F(PassSamples, RenderTakesPassesOfManySamplesAndGivesTheSameMean) {
    RenderSettings s;
    s.width = 40;
    s.height = 30;
    s.samplesPerPixel = kSamplesPerPass + 5; // a full pass and a short one
    const Framebuffer whole = render(scene_, bvh_, s);
    const Rendered single =
        renderInPasses(scene_, bvh_, s, FilmWindow{0, 0, s.width, s.height}, 0,
                       std::vector<uint32_t>(static_cast<std::size_t>(s.samplesPerPixel), 1));
    const Framebuffer expected = single.film.mean();
    ASSERT_EQ(whole.pixels.size(), expected.pixels.size());
    EXPECT_EQ(std::memcmp(whole.pixels.data(), expected.pixels.data(),
                          whole.pixels.size() * sizeof(glm::vec3)),
              0);
}

} // namespace
} // namespace raylab
