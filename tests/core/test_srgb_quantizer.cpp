// The table-driven sRGB quantizer against the pow formula it replaces, float by float.

#include "core/render/display_transform.h"
#include "core/render/srgb_quantizer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>

namespace raylab {
namespace {

float floatOf(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

TEST(SrgbQuantizer, EqualsTheFormulaOnEverySixteenthFloatBelowOne) {
    const SrgbQuantizer& srgb = srgbQuantizer();
    const uint32_t one = 0x3f800000u;
    uint64_t checked = 0;
    for (uint32_t bits = 0; bits <= one; bits += 16) {
        const float x = floatOf(bits);
        ASSERT_EQ(srgb(x), srgbByteByFormula(x)) << "x = " << x << " (bits " << bits << ")";
        ++checked;
    }
    EXPECT_GT(checked, 60'000'000u);
}

TEST(SrgbQuantizer, EveryStepIsWhereTheFormulaSteps) {
    const SrgbQuantizer& srgb = srgbQuantizer();
    for (int b = 1; b < 256; ++b) {
        const float first = srgb.firstOf(b);
        const float before = std::nextafter(first, 0.0f);
        EXPECT_EQ(srgbByteByFormula(first), b);
        EXPECT_EQ(srgbByteByFormula(before), b - 1) << "the formula skips or repeats a step";
        EXPECT_EQ(srgb(first), b);
        EXPECT_EQ(srgb(before), b - 1);
    }
}

// bucketTable()'s contract, for every float in [0, 1]: the formula's byte rises monotonically, so
// it holds in a whole bucket when it holds at its first and last float and around its step.
TEST(SrgbQuantizer, TheBucketTableGivesEveryByteWithOneComparison) {
    const uint32_t* table = srgbQuantizer().bucketTable();
    const auto byteOf = [&](uint32_t bits) {
        const uint32_t e = table[bits >> SrgbQuantizer::kBucketShift];
        return (e >> 16) + ((bits & SrgbQuantizer::kLowBits) >= (e & 0xffff) ? 1u : 0u);
    };
    for (uint32_t k = 0; k < SrgbQuantizer::kBuckets; ++k) {
        const uint32_t first = k << SrgbQuantizer::kBucketShift;
        const uint32_t last = std::min(first + SrgbQuantizer::kLowBits, 0x3f800000u);
        const uint32_t step = first + (table[k] & 0xffff);
        ASSERT_LE(table[k] >> 16, 255u);
        for (const uint32_t bits : {first, last, step - 1, step}) {
            if (bits >= first && bits <= last) {
                ASSERT_EQ(byteOf(bits), srgbByteByFormula(floatOf(bits)))
                    << "x = " << floatOf(bits) << " in bucket " << k;
            }
        }
        if (step > last) { // no step inside: the bucket is one byte
            ASSERT_EQ(srgbByteByFormula(floatOf(first)), srgbByteByFormula(floatOf(last)))
                << "bucket " << k;
        } else {
            ASSERT_EQ(srgbByteByFormula(floatOf(step - 1)), srgbByteByFormula(floatOf(first)))
                << "bucket " << k;
            ASSERT_EQ(srgbByteByFormula(floatOf(last)), srgbByteByFormula(floatOf(step)))
                << "bucket " << k << " holds two steps";
        }
    }
}

TEST(SrgbQuantizer, OutOfRangeValues) {
    const SrgbQuantizer& srgb = srgbQuantizer();
    EXPECT_EQ(srgb(-1.0f), 0);
    EXPECT_EQ(srgb(-0.0f), 0);
    EXPECT_EQ(srgb(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(srgb(std::numeric_limits<float>::denorm_min()), 0);
    EXPECT_EQ(srgb(1.0f), 255);
    EXPECT_EQ(srgb(3.0e38f), 255);
    EXPECT_EQ(srgb(std::numeric_limits<float>::infinity()), 255);
}

TEST(SrgbQuantizer, ImagesUseItWithExposure) {
    const std::vector<glm::vec3> pixels{{0.11f, 0.5f, 2.0f}, {0.0f, 0.001f, 0.3f}};
    std::vector<uint8_t> rgba(8);
    toRgba8(pixels, 0.5f, DisplayMode::Srgb, 1.0f, rgba); // scale 1/2, then 2 stops up: x2
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float exposed = pixels[i][c] * 0.5f * 2.0f;
            EXPECT_EQ(rgba[4 * i + static_cast<std::size_t>(c)], srgbByteByFormula(exposed));
        }
        EXPECT_EQ(rgba[4 * i + 3], 255);
    }
}

} // namespace
} // namespace raylab
