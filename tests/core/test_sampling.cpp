// The sampling room: Owen-scrambled Sobol points keep their stratification, PixelSampler is
// deterministic and in range, and the warps have the densities they state.

#include "core/sampling/sampler.h"
#include "core/sampling/sobol.h"
#include "core/sampling/warp.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <set>
#include <utility>
#include <vector>

namespace raylab {
namespace {

// Every elementary interval of area 2^-k (2^a by 2^(k-a) cells, for each a) holds exactly one of
// the first 2^k points: the (0, 2)-sequence property that scrambling must keep.
void expectStratified(const std::vector<glm::vec2>& points, int k) {
    const int n = 1 << k;
    ASSERT_EQ(points.size(), static_cast<std::size_t>(n));
    for (int a = 0; a <= k; ++a) {
        const int columns = 1 << a;
        const int rows = 1 << (k - a);
        std::set<std::pair<int, int>> cells;
        for (const glm::vec2& p : points) {
            cells.insert({static_cast<int>(p.x * static_cast<float>(columns)),
                          static_cast<int>(p.y * static_cast<float>(rows))});
        }
        EXPECT_EQ(cells.size(), static_cast<std::size_t>(n)) << columns << " x " << rows;
    }
}

TEST(Sampling, OwenScrambledSobolPrefixesAreStratifiedForEverySeedAndPair) {
    for (uint32_t pixel : {0u, 7u, 123456u}) {
        for (uint32_t pair : {0u, 1u, 5u, 33u}) {
            for (int k : {4, 6, 8}) {
                std::vector<glm::vec2> points;
                for (uint32_t i = 0; i < (1u << k); ++i) {
                    points.push_back(PixelSampler(SamplerKind::Sobol, pixel, i).get2D(pair));
                }
                expectStratified(points, k);
            }
        }
    }
}

TEST(Sampling, TheTabulatedSobolDimensionEqualsTheMatrixLoop) {
    for (uint32_t i = 0; i < 4096; ++i) {
        ASSERT_EQ(sobolDimension1(i), sobolDimension1Reference(i)) << i;
    }
    uint32_t x = 12345;
    for (int i = 0; i < 100000; ++i) {
        x = x * 1664525U + 1013904223U;
        ASSERT_EQ(sobolDimension1(x), sobolDimension1Reference(x)) << x;
    }
    // Its first values: 1/2, 3/4, 1/4 (Sobol's second dimension).
    EXPECT_EQ(sobolDimension1(1), 0x80000000U);
    EXPECT_EQ(sobolDimension1(2), 0xc0000000U);
    EXPECT_EQ(sobolDimension1(3), 0x40000000U);
}

TEST(Sampling, PixelSamplerIsTheScrambledSobolSequenceAsDefined) {
    // The sampler's shortcut (reversals that cancel left out) against the definition: the
    // index scrambled, then each dimension scrambled with its own seed.
    for (uint32_t pixel : {0u, 99u}) {
        for (uint32_t i = 0; i < 300; ++i) {
            for (uint32_t pair : {0u, 7u}) {
                const uint32_t pixelKey = hash32(pixel ^ hash32(0 + 0x68e31da4U));
                const uint32_t key = hash32(pixelKey ^ hash32(pair * 0x9e3779b9U + 0x7f4a7c15U));
                const uint32_t index = owenScramble(i, key);
                const glm::vec2 expected(
                    unitFloat(owenScramble(sobolDimension0(index), hash32(key ^ 0xa511e9b3U))),
                    unitFloat(owenScramble(sobolDimension1(index), hash32(key ^ 0x63d83595U))));
                ASSERT_EQ(PixelSampler(SamplerKind::Sobol, pixel, i).get2D(pair), expected);
            }
        }
    }
}

TEST(Sampling, IndependentPointsAreNotStratified) {
    // The baseline the Sobol points are compared with: white noise misses cells.
    std::vector<glm::vec2> points;
    for (uint32_t i = 0; i < 256; ++i) {
        points.push_back(PixelSampler(SamplerKind::Independent, 3, i).get2D(2));
    }
    std::set<std::pair<int, int>> cells;
    for (const glm::vec2& p : points) {
        cells.insert({static_cast<int>(p.x * 16.0f), static_cast<int>(p.y * 16.0f)});
    }
    EXPECT_LT(cells.size(), 256u);
    EXPECT_GT(cells.size(), 100u);
}

TEST(Sampling, OwenScrambleIsABijectionThatKeepsIntervals) {
    // Scrambling 8-bit prefixes: the 256 values 0..255 << 24 map to 256 distinct top bytes.
    for (uint32_t seed : {0u, 1u, 0xdeadbeefU}) {
        std::set<uint32_t> tops;
        for (uint32_t v = 0; v < 256; ++v) {
            tops.insert(owenScramble(v << 24, seed) >> 24);
        }
        EXPECT_EQ(tops.size(), 256u) << seed;
    }
    // Different seeds scramble differently.
    EXPECT_NE(owenScramble(0x12345678U, 1), owenScramble(0x12345678U, 2));
}

TEST(Sampling, PixelSamplerIsDeterministicInRangeAndDecorrelated) {
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent}) {
        double sum = 0.0;
        for (uint32_t i = 0; i < 4096; ++i) {
            const glm::vec2 u = PixelSampler(kind, 42, i).get2D(3);
            ASSERT_GE(u.x, 0.0f);
            ASSERT_LT(u.x, 1.0f);
            ASSERT_GE(u.y, 0.0f);
            ASSERT_LT(u.y, 1.0f);
            ASSERT_EQ(u, PixelSampler(kind, 42, i).get2D(3));
            sum += u.x + u.y;
        }
        EXPECT_NEAR(sum / 8192.0, 0.5, 0.01);
        EXPECT_NE(PixelSampler(kind, 1, 0).get2D(0), PixelSampler(kind, 2, 0).get2D(0));
        EXPECT_NE(PixelSampler(kind, 1, 0).get2D(0), PixelSampler(kind, 1, 0).get2D(1));
        EXPECT_NE(PixelSampler(kind, 1, 0, 0).get2D(0), PixelSampler(kind, 1, 0, 1).get2D(0));
    }
}

TEST(Warps, CosineHemisphereHasDensityCosineOverPi) {
    // E[cos] = 2/3 and E[cos^2] = 1/2 under density cos / pi; every direction is unit and up.
    double cosSum = 0.0;
    double cos2Sum = 0.0;
    const int n = 1 << 14;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 d = cosineHemisphere(
            PixelSampler(SamplerKind::Sobol, 0, static_cast<uint32_t>(i)).get2D(0));
        ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
        ASSERT_GE(d.z, 0.0f);
        cosSum += d.z;
        cos2Sum += d.z * d.z;
    }
    EXPECT_NEAR(cosSum / n, 2.0 / 3.0, 2e-3);
    EXPECT_NEAR(cos2Sum / n, 0.5, 2e-3);
}

TEST(Warps, UniformConeStaysInsideAndIsUniformInSolidAngle) {
    const float oneMinusCosMax = 0.1f;
    double cosSum = 0.0;
    const int n = 1 << 14;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 d = uniformCone(
            PixelSampler(SamplerKind::Sobol, 9, static_cast<uint32_t>(i)).get2D(0), oneMinusCosMax);
        ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
        ASSERT_GE(d.z, 1.0f - oneMinusCosMax - 1e-6f);
        cosSum += d.z;
    }
    // Uniform in solid angle: cos(theta) is uniform on [cos max, 1].
    EXPECT_NEAR(cosSum / n, 1.0 - 0.5 * oneMinusCosMax, 1e-4);
}

TEST(Warps, FramesAreOrthonormalAroundTheirAxis) {
    for (const glm::vec3& n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0),
                               glm::normalize(glm::vec3(0.3f, -0.8f, 0.1f))}) {
        const Frame f = frameAround(n);
        EXPECT_NEAR(glm::dot(f.x, f.y), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(f.x, f.z), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(f.y, f.z), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::length(f.x), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::length(f.y), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::length(f.toWorld({0, 0, 1}) - n), 0.0f, 1e-6f);
    }
}

TEST(Warps, UniformTriangleCoversTheTriangleEvenly) {
    // Barycentrics inside the triangle; each of the four mid-point sub-triangles gets a quarter.
    int counts[4] = {0, 0, 0, 0};
    const int n = 1 << 12;
    for (int i = 0; i < n; ++i) {
        const glm::vec2 b =
            uniformTriangle(PixelSampler(SamplerKind::Sobol, 5, static_cast<uint32_t>(i)).get2D(1));
        ASSERT_GE(b.x, 0.0f);
        ASSERT_GE(b.y, 0.0f);
        ASSERT_LE(b.x + b.y, 1.0f + 1e-6f);
        const int region = b.x > 0.5f ? 0 : b.y > 0.5f ? 1 : (b.x + b.y < 0.5f ? 2 : 3);
        ++counts[region];
    }
    for (int c : counts) {
        EXPECT_NEAR(static_cast<double>(c) / n, 0.25, 0.02);
    }
}

} // namespace
} // namespace raylab
