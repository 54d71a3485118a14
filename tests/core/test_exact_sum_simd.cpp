// Eight pixels' samples added at once (exact_sum_simd.h) give the scalar PixelSum::add's sums bit
// for bit: across every exponent of toFixed's exact range, both signs, zeros, sums that carry
// into and borrow from the high word, and values outside the range (which take the scalar
// path). The AVX-512 path is tested where the CPU has it.

#include "core/render/exact_sum_simd.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

namespace raylab {
namespace {

// Deterministic floats of every exponent in [lowExp, highExp), random significands and signs.
std::vector<float> floatsBetween(int lowExp, int highExp, uint32_t seed, std::size_t count) {
    std::vector<float> out(count);
    uint32_t state = seed;
    const auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return state;
    };
    for (float& x : out) {
        const int exponent =
            lowExp + static_cast<int>(next() % static_cast<uint32_t>(highExp - lowExp));
        const float significand = 1.0f + static_cast<float>(next() >> 9) * 0x1p-23f;
        x = std::ldexp(significand, exponent) * ((next() & 1u) != 0 ? -1.0f : 1.0f);
    }
    return out;
}

// The SoA lanes of 8 pixels whose samples are rgb[3k..3k+2] (the tests write them pixel by pixel).
struct Lanes {
    float r[8], g[8], b[8];
    explicit Lanes(const float* rgb) {
        for (int k = 0; k < 8; ++k) {
            r[k] = rgb[3 * k];
            g[k] = rgb[3 * k + 1];
            b[k] = rgb[3 * k + 2];
        }
    }
};

void addScalar(PixelSum* sums, const float* rgb) {
    const Lanes l(rgb);
    addSamples8Scalar(sums, l.r, l.g, l.b);
}
bool addAvx512(PixelSum* sums, const float* rgb) {
    const Lanes l(rgb);
    return addSamples8Avx512(sums, l.r, l.g, l.b);
}

void expectSameSums(const std::vector<float>& samples, int passes) {
    ASSERT_EQ(samples.size() % 24, 0u);
    const std::size_t groups = samples.size() / 24;
    std::vector<PixelSum> scalar(8 * groups);
    std::vector<PixelSum> simd(8 * groups);
    int simdGroups = 0;
    for (int pass = 0; pass < passes; ++pass) {
        for (std::size_t g = 0; g < groups; ++g) {
            // Each pass adds the groups' samples rotated, so sums mix values.
            const std::size_t from = ((g + static_cast<std::size_t>(pass)) % groups) * 24;
            addScalar(&scalar[8 * g], &samples[from]);
            if (addAvx512(&simd[8 * g], &samples[from])) {
                ++simdGroups;
            } else {
                addScalar(&simd[8 * g], &samples[from]);
            }
        }
    }
    int differing = 0;
    for (std::size_t i = 0; i < scalar.size(); ++i) {
        differing += scalar[i] == simd[i] ? 0 : 1;
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(simdGroups, 0) << "no group took the AVX-512 path";
}

class ExactSumSimd : public ::testing::Test {
protected:
    void SetUp() override {
        if (!avx512Supported()) {
            GTEST_SKIP() << "this CPU has no AVX-512 (F and DQ): only the scalar path runs";
        }
    }
};

TEST_F(ExactSumSimd, EveryExponentOfTheExactRangeAddsAsTheScalarPath) {
    expectSameSums(floatsBetween(-40, 31, 7u, 24 * 4096), 3);
}

TEST_F(ExactSumSimd, RadianceLikeValuesOverManyPassesAddAsTheScalarPath) {
    // Positive values about 1, as the lab's R: sums that carry from the low word to the high.
    std::vector<float> samples = floatsBetween(-12, 4, 11u, 24 * 512);
    for (float& x : samples) {
        x = std::fabs(x);
    }
    expectSameSums(samples, 200);
}

TEST_F(ExactSumSimd, ZerosAndTheRangesEdgesAddAsTheScalarPath) {
    std::vector<float> samples;
    const float edges[] = {0.0f, -0.0f, 0x1p-40f, -0x1p-40f, 0x1.fffffep30f,  -0x1.fffffep30f,
                           1.0f, -1.0f, 0x1p-28f, 0x1p11f,   0x1.fffffep-29f, 0.5f};
    for (int i = 0; i < 24 * 8; ++i) {
        samples.push_back(edges[static_cast<std::size_t>(i * 7) % std::size(edges)]);
    }
    expectSameSums(samples, 5);
}

TEST_F(ExactSumSimd, ValuesOutsideTheRangeTakeTheScalarPathAndAddNothingFirst) {
    const float outside[] = {std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::infinity(),
                             0x1p31f,
                             -0x1p40f,
                             0x1p-41f,
                             std::numeric_limits<float>::denorm_min()};
    for (const float bad : outside) {
        std::vector<float> samples(24, 0.25f);
        samples[13] = bad;
        PixelSum sums[8];
        EXPECT_FALSE(addAvx512(sums, samples.data())) << bad;
        for (const PixelSum& s : sums) {
            EXPECT_EQ(s, PixelSum{}); // nothing added
        }
        PixelSum viaDispatch[8];
        PixelSum viaScalar[8];
        const Lanes l(samples.data());
        addSamples8(viaDispatch, l.r, l.g, l.b);
        addSamples8Scalar(viaScalar, l.r, l.g, l.b);
        for (int k = 0; k < 8; ++k) {
            EXPECT_EQ(viaDispatch[k], viaScalar[k]);
        }
    }
}

} // namespace
} // namespace raylab
