// The film: accumulation, restart and resume, the mean and display bytes, the noise estimate and
// the mean indirect term.

#include "core/render/film.h"
#include "core/render/image_error.h"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace raylab {
namespace {

TEST(Film, MeanIsTheSumsTimesOneOverSamples) {
    Film film(3, 2);
    EXPECT_EQ(film.samples(), 0u);
    EXPECT_EQ(film.scale(), 0.0f);
    for (std::size_t i = 0; i < film.pixelCount(); ++i) {
        film.sums()[i] = glm::vec3(static_cast<float>(i), 1.0f, 3.0f);
    }
    film.resume(3);
    const Framebuffer mean = film.mean();
    ASSERT_EQ(mean.width, 3);
    ASSERT_EQ(mean.height, 2);
    for (std::size_t i = 0; i < film.pixelCount(); ++i) {
        EXPECT_EQ(mean.pixels[i], film.sums()[i] * (1.0f / 3.0f));
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
            film.sums()[p] = s == 0 ? v : film.sums()[p] + v;
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
