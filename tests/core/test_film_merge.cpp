// Adding up parts of a render (render/film_merge.h): films of sample ranges and windows, rendered
// apart, merge to the film rendered in one go, bit for bit, for both integrators; parts that do
// not cover every pixel's samples once are refused with the pixels and samples named.

#include "core/bvh/bvh.h"
#include "core/cornell_box.h"
#include "core/render/film_merge.h"
#include "core/render/renderer.h"

#include <gtest/gtest.h>
#include <vector>

namespace raylab {
namespace {

struct RenderedPart {
    Film film;
    std::vector<PixelSum> sums;
};

RenderedPart renderPart(const Scene& scene, const Bvh& bvh, const RenderSettings& s,
                        FilmWindow window, uint32_t first, uint32_t end) {
    RenderedPart part;
    part.film.reset(window, filmLayersFor(s));
    part.film.startAt(first);
    for (uint32_t i = first; i < end; ++i) {
        EXPECT_TRUE(renderPass(scene, bvh, s, part.film));
    }
    part.sums.resize(part.film.pixelCount());
    for (std::size_t i = 0; i < part.sums.size(); ++i) {
        part.sums[i] = part.film.sumOf(i);
    }
    return part;
}

// The lab's box and its BVH, shared by the tests; settings of the given size.
class FilmMerge : public ::testing::Test {
protected:
    static RenderSettings sized(int width, int height) {
        RenderSettings s;
        s.width = width;
        s.height = height;
        return s;
    }
    RenderedPart part(const RenderSettings& s, FilmWindow window, uint32_t first, uint32_t end) {
        return renderPart(scene_, bvh_, s, window, first, end);
    }
    Scene scene_ = makeCornellBox();
    Bvh bvh_ = buildBvh(scene_);
};

FilmPart asPart(const RenderedPart& part, const char* name) {
    return {name,      part.film.window(), part.film.firstSample(), part.film.nextSample(),
            part.sums, part.film.squares()};
}

TEST_F(FilmMerge, RangesAndWindowsMergeToTheWholeRenderBitForBit) {
    for (Integrator integrator : {Integrator::Lab, Integrator::Path}) {
        RenderSettings s = sized(37, 29);
        s.integrator = integrator;
        s.light.radius = 0.05f;
        s.threads = 2;
        const RenderedPart whole = part(s, {0, 0, 37, 29}, 0, 5);
        // Left: samples 0:2 and 2:5; right: one part, over two rows of windows.
        const RenderedPart pieces[] = {
            part(s, {0, 0, 20, 29}, 0, 2),
            part(s, {0, 0, 20, 29}, 2, 5),
            part(s, {20, 0, 37, 11}, 0, 5),
            part(s, {20, 11, 37, 29}, 0, 5),
        };
        const std::vector<FilmPart> given = {asPart(pieces[3], "d"), asPart(pieces[1], "b"),
                                             asPart(pieces[0], "a"), asPart(pieces[2], "c")};
        Film merged;
        ASSERT_EQ(mergeFilmParts(37, 29, given, merged), "");
        ASSERT_EQ(merged.samples(), 5u);
        for (std::size_t i = 0; i < merged.pixelCount(); ++i) {
            ASSERT_EQ(merged.sumOf(i), whole.film.sumOf(i)) << "pixel " << i;
            ASSERT_EQ(merged.mean(i), whole.film.mean(i));
        }
        // The path integrator's films keep noise moments, and so does their merge.
        EXPECT_EQ(merged.noise().known, integrator == Integrator::Path);
    }
}

TEST_F(FilmMerge, OneSampleMergesKeepTheSamplesFloats) {
    const RenderSettings s = sized(16, 12);
    const RenderedPart whole = part(s, {0, 0, 16, 12}, 0, 1);
    const RenderedPart top = part(s, {0, 0, 16, 5}, 0, 1);
    const RenderedPart bottom = part(s, {0, 5, 16, 12}, 0, 1);
    const std::vector<FilmPart> given = {asPart(top, "top"), asPart(bottom, "bottom")};
    Film merged;
    ASSERT_EQ(mergeFilmParts(16, 12, given, merged), "");
    for (std::size_t i = 0; i < merged.pixelCount(); ++i) {
        ASSERT_EQ(merged.mean(i), whole.film.mean(i));
    }
}

TEST_F(FilmMerge, GapsAndOverlapsAreNamed) {
    const RenderSettings s = sized(10, 10);
    const RenderedPart a = part(s, {0, 0, 10, 10}, 0, 2);
    const RenderedPart b = part(s, {0, 0, 10, 10}, 3, 4);
    const RenderedPart c = part(s, {0, 0, 10, 10}, 1, 3);
    const RenderedPart corner = part(s, {0, 0, 4, 4}, 2, 4);
    Film merged;
    EXPECT_EQ(mergeFilmParts(10, 10, std::vector<FilmPart>{asPart(a, "a"), asPart(b, "b")}, merged),
              "samples 2:3 of pixels 0,0 to 10,10 are missing");
    EXPECT_EQ(mergeFilmParts(10, 10, std::vector<FilmPart>{asPart(a, "a"), asPart(c, "c")}, merged),
              "samples 1:2 of pixels 0,0 to 10,10 are in two parts (c and another)");
    EXPECT_EQ(
        mergeFilmParts(10, 10, std::vector<FilmPart>{asPart(a, "a"), asPart(corner, "k")}, merged),
        "samples 2:4 of pixels 4,0 to 10,4 are missing");
    EXPECT_EQ(mergeFilmParts(12, 10, std::vector<FilmPart>{asPart(a, "a")}, merged),
              "samples 0:2 of pixels 10,0 to 12,10 are missing");
    EXPECT_EQ(mergeFilmParts(8, 10, std::vector<FilmPart>{asPart(a, "a")}, merged),
              "a: its window or range does not fit the picture");
    EXPECT_EQ(mergeFilmParts(10, 10, std::vector<FilmPart>{}, merged), "no parts to merge");
}

} // namespace
} // namespace raylab
