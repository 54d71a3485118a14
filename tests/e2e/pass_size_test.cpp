// The viewer's pass size: one sample while the picture is young or a pass is slow, growing with
// the picture to a quarter of its samples, within the time budget, kSamplesPerPass and the cap.

#include "core/render/renderer.h"
#include "pass_size.h"

#include <gtest/gtest.h>

namespace raylab {
namespace {

constexpr std::size_t kPixels = 1280 * 720;
// A lab pass at 50 M samples/s: 18 ms for one sample of 1280 x 720.
constexpr double kFast = 1.0 / 50e6;

TEST(PassSize, OneSampleWhileThePictureIsYoung) {
    for (uint32_t held = 0; held < 8; ++held) {
        EXPECT_EQ(passSamples(held, 1000, kFast, kPixels), 1u) << held;
    }
    EXPECT_EQ(passSamples(100, 1000, 0.0, kPixels), 1u); // nothing measured yet
}

TEST(PassSize, GrowsToAQuarterOfTheSamplesHeldWithinTheBudget) {
    // A tenth of the picture's pass of one sample: up to kSamplesPerPass fit 100 ms.
    const double cheap = kFast / 10.0;
    EXPECT_EQ(passSamples(8, 1000, cheap, kPixels), 2u);
    EXPECT_EQ(passSamples(12, 1000, cheap, kPixels), 3u);
    EXPECT_EQ(passSamples(40, 1000, cheap, kPixels), 10u);
    EXPECT_EQ(passSamples(500, 1000, cheap, kPixels), static_cast<uint32_t>(kSamplesPerPass));
    // 18 ms a sample: four fit 100 ms, not eight.
    EXPECT_EQ(passSamples(500, 1000, kFast, kPixels), 4u);
    // A slow pass (the path integrator): one at a time.
    EXPECT_EQ(passSamples(500, 1000, 1.0 / 2e6, kPixels), 1u);
    for (uint32_t held = 1; held < 300; held += 7) {
        const uint32_t n = passSamples(held, 100000, kFast / 3.0, kPixels);
        EXPECT_LE(static_cast<double>(n) * kFast / 3.0 * kPixels,
                  std::max(kConvergingPassSeconds, kFast / 3.0 * kPixels));
        EXPECT_LE(n, std::max(held / 4, 1u));
    }
}

TEST(PassSize, NeverPastTheCap) {
    const double cheap = kFast / 10.0;
    EXPECT_EQ(passSamples(60, 64, cheap, kPixels), 4u);
    EXPECT_EQ(passSamples(63, 64, cheap, kPixels), 1u);
    EXPECT_EQ(passSamples(62, 64, cheap, kPixels), 2u);
}

} // namespace
} // namespace raylab
