// The film: accumulation, restart and resume, the mean and display bytes, the noise estimate and
// the mean indirect term.

#include "core/render/film.h"
#include "core/render/image_error.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace raylab {
namespace {

TEST(Film, MeanIsTheSumsOverTheSamples) {
    Film film(3, 2);
    EXPECT_EQ(film.samples(), 0u);
    EXPECT_EQ(film.mean().pixels[0], glm::vec3(0.0f));
    std::vector<PixelSum> sums(film.pixelCount());
    for (std::size_t i = 0; i < film.pixelCount(); ++i) {
        sums[i].store(glm::vec3(static_cast<float>(i), 1.0f, 3.0f));
    }
    film.assign(sums, 0, 3);
    const Framebuffer mean = film.mean();
    ASSERT_EQ(mean.width, 3);
    ASSERT_EQ(mean.height, 2);
    for (std::size_t i = 0; i < film.pixelCount(); ++i) {
        EXPECT_EQ(mean.pixels[i], glm::vec3(static_cast<float>(static_cast<double>(i) / 3.0),
                                            static_cast<float>(1.0 / 3.0), 1.0f));
    }
    std::vector<uint8_t> bytes(4 * film.pixelCount());
    film.toDisplay(bytes, DisplayMode::Lab, 0.0f);
    EXPECT_EQ(bytes[4 * 0 + 0], 0);   // 0 / 3
    EXPECT_EQ(bytes[4 * 0 + 1], 85);  // 1 / 3 of 255
    EXPECT_EQ(bytes[4 * 0 + 2], 255); // 3 / 3
    EXPECT_EQ(bytes[4 * 5 + 0], 255); // 5 / 3, clamped
    film.passFinished();
    EXPECT_EQ(film.samples(), 4u);
    film.restart();
    EXPECT_EQ(film.samples(), 0u);
}

TEST(Film, ResetKeepsOnlyTheLayersAskedFor) {
    Film film(4, 4, FilmLayers{true, false});
    EXPECT_EQ(film.squares().size(), 16u);
    EXPECT_TRUE(film.indirect().empty());
    film.reset(2, 8, FilmLayers{false, true});
    EXPECT_TRUE(film.squares().empty());
    EXPECT_EQ(film.indirect().size(), 16u);
    EXPECT_FALSE(film.noise().known);
}

TEST(Film, TheNoiseEstimateMatchesTheErrorAgainstTheTrueMean) {
    // Pixels whose samples are normal with mean 1 and standard deviation 0.5: after n samples
    // the relative error of the image is 0.5 / sqrt(n), both as estimated from the moments and
    // as measured against the true image.
    const int pixels = 4096;
    Film film(64, 64, FilmLayers{true, false});
    std::mt19937 random(7);
    std::normal_distribution<float> sample(1.0f, 0.5f);
    const int n = 16;
    for (int s = 0; s < n; ++s) {
        for (int p = 0; p < pixels; ++p) {
            const glm::vec3 v(sample(random), sample(random), sample(random));
            film.write(static_cast<std::size_t>(p), v, film.nextWrite());
            film.squares()[p] = s == 0 ? v * v : film.squares()[p] + v * v;
        }
        film.passFinished();
    }
    const NoiseEstimate noise = film.noise();
    ASSERT_TRUE(noise.known);
    const double expected = 0.5 / std::sqrt(static_cast<double>(n));
    EXPECT_NEAR(noise.relativeError, expected, 0.03 * expected);
    Framebuffer truth(64, 64);
    std::fill(truth.pixels.begin(), truth.pixels.end(), glm::vec3(1.0f));
    EXPECT_NEAR(relativeRmse(film.mean(), truth), expected, 0.03 * expected);
}

TEST(Film, MeanIndirectAveragesOverSamplesThatHit) {
    Film film(2, 1, FilmLayers{false, true});
    film.indirect()[0] = glm::vec4(2.0f, 4.0f, 6.0f, 2.0f); // two hits
    film.indirect()[1] = glm::vec4(0.0f, 0.0f, 0.0f, 0.0f); // misses only
    film.resume(2);
    EXPECT_EQ(film.meanIndirect(), glm::vec3(1.0f, 2.0f, 3.0f));
    Film none(2, 1);
    EXPECT_EQ(none.meanIndirect(), glm::vec3(0.0f));
}

TEST(ExactSum, OneSampleComesBackExactly) {
    std::mt19937 random(3);
    std::uniform_real_distribution<float> exponent(-40.0f, 30.0f);
    for (int i = 0; i < 100000; ++i) {
        const float x = std::ldexp(1.0f + static_cast<float>(random() & 0xffffff) * 0x1p-24f,
                                   static_cast<int>(exponent(random)));
        ASSERT_EQ(static_cast<float>(fromFixed(toFixed(x))), x) << x;
        ASSERT_EQ(static_cast<float>(fromFixed(toFixed(-x))), -x) << x;
    }
    EXPECT_EQ(fromFixed(toFixed(0.0f)), 0.0);
    EXPECT_EQ(fromFixed(toFixed(std::nanf(""))), 0.0);
    EXPECT_EQ(fromFixed(toFixed(1e-30f)), 0.0); // below 2^-63: dropped
    EXPECT_FALSE(representable(1e-30f));
    EXPECT_EQ(asStored(1e-30f), 0.0f);
    EXPECT_EQ(asStored(0.3f), 0.3f);
    EXPECT_EQ(fromFixed(toFixed(INFINITY)), 0x1p31);
    EXPECT_EQ(fromFixed(toFixed(-1e20f)), -0x1p31);
    // The most samples a film counts, each at the clamp, still sum without overflow.
    const FixedSum big = toFixed(1e30f) * static_cast<FixedSum>(0xffffffffu);
    EXPECT_EQ(fromFixed(big), 0x1p63 - 0x1p31);
}

TEST(ExactSum, SumsDoNotDependOnTheOrder) {
    // Values of very different sizes, whose float sums differ with the order of addition.
    std::mt19937 random(11);
    std::uniform_real_distribution<float> exponent(-30.0f, 20.0f);
    std::vector<float> values(1000);
    for (float& v : values) {
        v = std::exp2(exponent(random)) * ((random() & 1) ? 1.0f : -0.5f);
    }
    const auto exactSum = [](const std::vector<float>& in) {
        FixedSum sum = 0;
        for (float v : in) {
            sum += toFixed(v);
        }
        return sum;
    };
    const auto floatSum = [](const std::vector<float>& in) {
        float sum = 0.0f;
        for (float v : in) {
            sum += v;
        }
        return sum;
    };
    const FixedSum forwards = exactSum(values);
    const float floatForwards = floatSum(values);
    int floatDiffers = 0;
    for (int shuffle = 0; shuffle < 20; ++shuffle) {
        std::shuffle(values.begin(), values.end(), random);
        ASSERT_TRUE(exactSum(values) == forwards);
        floatDiffers += floatSum(values) != floatForwards;
    }
    EXPECT_GT(floatDiffers, 0) << "the values do not show the float sums' order dependence";
    // And the exact sum is the true one (long double has 64 mantissa bits, enough here).
    long double truth = 0.0L;
    for (float v : values) {
        truth += static_cast<long double>(v);
    }
    EXPECT_NEAR(static_cast<double>(fromFixed(forwards)), static_cast<double>(truth),
                1e-15 * std::fabs(static_cast<double>(truth)) + 1e-12);
}

TEST(Film, ARangeStartsWhereItIsToldAndAWindowIndexesImagePixels) {
    Film film(FilmWindow{10, 20, 14, 23});
    EXPECT_EQ(film.width(), 4);
    EXPECT_EQ(film.height(), 3);
    EXPECT_EQ(film.pixelCount(), 12u);
    EXPECT_EQ(film.indexOf(10, 20), 0u);
    EXPECT_EQ(film.indexOf(13, 22), 11u);
    film.startAt(8);
    EXPECT_EQ(film.samples(), 0u);
    EXPECT_EQ(film.nextSample(), 8u);
    EXPECT_EQ(film.nextWrite(), Film::Write::First);
    film.passFinished();
    film.passFinished();
    EXPECT_EQ(film.samples(), 2u);
    EXPECT_EQ(film.firstSample(), 8u);
    EXPECT_EQ(film.nextSample(), 10u);
    EXPECT_EQ(film.nextWrite(), Film::Write::Later);
    EXPECT_EQ(film.nextWrite(), Film::Write::Later);
    film.restart();
    EXPECT_EQ(film.nextSample(), 8u);
    EXPECT_EQ(film.nextWrite(), Film::Write::First);
}

TEST(ImageError, RelativeRmseIsZeroForEqualImagesAndScalesWithTheError) {
    Framebuffer reference(2, 2);
    std::fill(reference.pixels.begin(), reference.pixels.end(), glm::vec3(2.0f));
    EXPECT_EQ(relativeRmse(reference, reference), 0.0);
    Framebuffer off = reference;
    for (glm::vec3& p : off.pixels) {
        p += glm::vec3(0.2f);
    }
    EXPECT_NEAR(relativeRmse(off, reference), 0.1, 1e-6);
    EXPECT_TRUE(std::isinf(relativeRmse(Framebuffer(3, 2), reference)));
    off.pixels[0].x = std::nanf("");
    EXPECT_TRUE(std::isinf(relativeRmse(off, reference)));
}

} // namespace
} // namespace raylab
