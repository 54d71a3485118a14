// Display transforms: the lab's clamp and sRGB with exposure.

#include "core/bvh/bvh.h"
#include "core/render/display_transform.h"
#include "core/render/srgb_quantizer.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <ostream>
#include <span>
#include <sstream>
#include <vector>

namespace raylab {
namespace {

TEST(DisplayTransform, LabClampsAndScalesWithoutGamma) {
    EXPECT_EQ(displayChannel(0.0f, DisplayMode::Lab, 0.0f), 0);
    EXPECT_EQ(displayChannel(-3.0f, DisplayMode::Lab, 0.0f), 0);
    EXPECT_EQ(displayChannel(0.5f, DisplayMode::Lab, 0.0f), 128); // 127.5 rounds up
    EXPECT_EQ(displayChannel(0.2f, DisplayMode::Lab, 0.0f), 51);
    EXPECT_EQ(displayChannel(1.0f, DisplayMode::Lab, 0.0f), 255);
    EXPECT_EQ(displayChannel(7.0f, DisplayMode::Lab, 0.0f), 255);
    EXPECT_EQ(displayChannel(0.5f, DisplayMode::Lab, 3.0f), 128) << "exposure is sRGB only";
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::quiet_NaN(), DisplayMode::Lab, 0.0f), 0);
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::infinity(), DisplayMode::Lab, 0.0f), 255);
}

TEST(DisplayTransform, SrgbFollowsTheTransferCurveAndExposure) {
    EXPECT_EQ(displayChannel(0.0f, DisplayMode::Srgb, 0.0f), 0);
    EXPECT_EQ(displayChannel(1.0f, DisplayMode::Srgb, 0.0f), 255);
    // 0.22 linear is 0.5064 in sRGB: 129.13 of 255.
    EXPECT_EQ(displayChannel(0.22f, DisplayMode::Srgb, 0.0f), 129);
    EXPECT_EQ(displayChannel(0.5f, DisplayMode::Srgb, 0.0f), 188); // 187.52
    // The linear segment near black: 0.001 -> 12.92 * 0.001 * 255 = 3.29.
    EXPECT_EQ(displayChannel(0.001f, DisplayMode::Srgb, 0.0f), 3);
    // One stop of exposure doubles the linear value.
    EXPECT_EQ(displayChannel(0.11f, DisplayMode::Srgb, 1.0f), 129);
    EXPECT_EQ(displayChannel(0.44f, DisplayMode::Srgb, -1.0f), 129);
    EXPECT_EQ(displayChannel(std::numeric_limits<float>::quiet_NaN(), DisplayMode::Srgb, 0.0f), 0);
}

TEST(DisplayTransform, ImagesBecomeRowMajorRgbaWithOpaqueAlpha) {
    Framebuffer image(2, 1);
    image.at(0, 0) = {1.0f, 0.0f, 0.5f};
    image.at(1, 0) = {0.2f, 2.0f, -1.0f};
    const std::vector<uint8_t> rgba = toRgba8(image, DisplayMode::Lab, 0.0f);
    const std::vector<uint8_t> expected = {255, 0, 128, 255, 51, 255, 0, 255};
    EXPECT_EQ(rgba, expected);

    // The scale divides an accumulation buffer of sums by its sample count.
    std::vector<glm::vec3> sums = {{2.0f, 1.0f, 0.4f}};
    std::vector<uint8_t> out(4);
    toRgba8(sums, 0.5f, DisplayMode::Lab, 0.0f, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{255, 128, 51, 255}));
}

// toRgba8's AVX2 path against toRgba8Scalar, byte for byte (skipped on CPUs without AVX2, where
// toRgba8 is the scalar loop).

struct Transform {
    float scale;
    DisplayMode mode;
    float exposure;
};

std::ostream& operator<<(std::ostream& os, const Transform& t) {
    return os << (t.mode == DisplayMode::Lab ? "lab" : "srgb") << " scale " << t.scale
              << " exposure " << t.exposure;
}

// Scales 1 / 3 and exposure -0.7 round; 0.5 with exposure 1 keeps sRGB steps exact.
const Transform kTransforms[] = {
    {1.0f, DisplayMode::Lab, 0.0f},         {1.0f / 3.0f, DisplayMode::Lab, 0.0f},
    {1.0f, DisplayMode::Srgb, 0.0f},        {0.5f, DisplayMode::Srgb, 1.0f},
    {1.0f / 3.0f, DisplayMode::Srgb, 1.0f}, {1.0f, DisplayMode::Srgb, -0.7f},
};

float floatOf(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

// Pixels from consecutive floats, the last one padded with zeros.
std::vector<glm::vec3> pixelsOf(const std::vector<float>& floats) {
    std::vector<glm::vec3> pixels((floats.size() + 2) / 3, glm::vec3(0.0f));
    std::memcpy(pixels.data(), floats.data(), floats.size() * sizeof(float));
    return pixels;
}

// toRgba8 and toRgba8Scalar write the same bytes into rgba[offset, offset + 4n) and nothing else.
::testing::AssertionResult sameAsScalar(std::span<const glm::vec3> pixels, const Transform& t,
                                        std::size_t offset = 0) {
    const std::size_t size = 4 * pixels.size() + offset + 32;
    std::vector<uint8_t> simd(size, 0xab), scalar(size, 0xab);
    toRgba8(pixels, t.scale, t.mode, t.exposure, std::span(simd).subspan(offset));
    toRgba8Scalar(pixels, t.scale, t.mode, t.exposure, std::span(scalar).subspan(offset));
    for (std::size_t i = 0; i < size; ++i) {
        if (simd[i] != scalar[i]) {
            auto failure = ::testing::AssertionFailure()
                           << t << ", " << pixels.size() << " pixels, byte " << i << ": "
                           << int(simd[i]) << " instead of " << int(scalar[i]);
            if (i >= offset && i < offset + 4 * pixels.size() && (i - offset) % 4 < 3) {
                const float x = pixels[(i - offset) / 4][static_cast<int>((i - offset) % 4)];
                uint32_t bits;
                std::memcpy(&bits, &x, sizeof bits);
                std::ostringstream hex;
                hex << std::hex << bits;
                failure << " for " << x << " (bits 0x" << hex.str() << ")";
            }
            return failure;
        }
    }
    return ::testing::AssertionSuccess();
}

TEST(DisplayTransformAvx2, EqualsScalarOnEverySixteenthFloatUpToOneAndAHalf) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    const uint32_t end = 0x3fc00000u; // 1.5f
    for (std::size_t n = 0; n < std::size(kTransforms); ++n) {
        std::vector<float> floats;
        // Each transform starts at another bit offset: together they see more patterns.
        for (uint64_t bits = n; bits <= end; bits += 16) {
            floats.push_back(floatOf(static_cast<uint32_t>(bits)));
            if (floats.size() == 3 * 4096 || bits + 16 > end) {
                ASSERT_TRUE(sameAsScalar(pixelsOf(floats), kTransforms[n]));
                floats.clear();
            }
        }
    }
}

TEST(DisplayTransformAvx2, EqualsScalarOnSpecialValuesAndSteps) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    using limits = std::numeric_limits<float>;
    std::vector<float> specials = {limits::quiet_NaN(),
                                   -limits::quiet_NaN(),
                                   limits::signaling_NaN(),
                                   floatOf(0x7fc12345u),
                                   floatOf(0xff812345u),
                                   floatOf(0x7f800001u), // NaN payloads
                                   limits::infinity(),
                                   -limits::infinity(),
                                   0.0f,
                                   -0.0f,
                                   limits::min(),
                                   -limits::min(),
                                   limits::denorm_min(),
                                   -limits::denorm_min(),
                                   floatOf(0x007fffffu),
                                   limits::max(),
                                   -limits::max(),
                                   1.0f,
                                   std::nextafter(1.0f, 0.0f),
                                   std::nextafter(1.0f, 2.0f),
                                   -1.0f,
                                   0.5f,
                                   255.0f,
                                   1e-30f};
    // The lab's rounding steps, (k + 0.5) / 255, and the floats around them.
    for (int k = 0; k <= 255; ++k) {
        float x = (static_cast<float>(k) + 0.5f) / 255.0f;
        specials.push_back(static_cast<float>(k) / 255.0f);
        for (int i = 0; i < 2; ++i) {
            x = std::nextafter(x, 0.0f);
        }
        for (int i = 0; i < 5; ++i, x = std::nextafter(x, 2.0f)) {
            specials.push_back(x);
        }
    }
    const SrgbQuantizer& srgb = srgbQuantizer();
    for (int b = 1; b <= 255; ++b) {
        specials.push_back(srgb.firstOf(b));
        specials.push_back(std::nextafter(srgb.firstOf(b), 0.0f));
    }
    std::vector<Transform> transforms(std::begin(kTransforms), std::end(kTransforms));
    transforms.push_back({1e30f, DisplayMode::Lab, 0.0f});
    transforms.push_back({1e30f, DisplayMode::Srgb, 0.0f});
    transforms.push_back({1e-30f, DisplayMode::Srgb, 3.0f});
    for (const Transform& t : transforms) {
        // Every value in every one of the 24 float positions of 8 pixels.
        for (std::size_t shift = 0; shift < 24; ++shift) {
            std::vector<float> floats(shift, 0.25f);
            floats.insert(floats.end(), specials.begin(), specials.end());
            ASSERT_TRUE(sameAsScalar(pixelsOf(floats), t)) << "shift " << shift;
        }
    }
}

TEST(DisplayTransformAvx2, EqualsScalarOnShortAndMisalignedSpans) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    std::vector<float> floats;
    for (int i = 0; i < 3 * 24; ++i) {
        floats.push_back(-0.2f + 0.023f * static_cast<float>(i)); // -0.2 to 1.43
    }
    const std::vector<glm::vec3> pixels = pixelsOf(floats);
    for (const Transform& t : kTransforms) {
        for (std::size_t count = 0; count <= 20; ++count) {
            for (const std::size_t first : {0, 1, 3}) { // 12 and 36 bytes off
                for (const std::size_t offset : {0, 1}) {
                    ASSERT_TRUE(sameAsScalar(std::span(pixels).subspan(first, count), t, offset))
                        << "first " << first << ", output offset " << offset;
                }
            }
        }
    }
}

// PixelOrder::Bgra writes the Rgba bytes with red and blue swapped, on both paths and for every
// length (the AVX2 groups of 8 and the scalar tail).
TEST(DisplayTransform, BgraSwapsRedAndBlue) {
    std::vector<glm::vec3> pixels;
    for (int i = 0; i < 37; ++i) {
        pixels.emplace_back(0.03f * static_cast<float>(i), 0.5f,
                            1.0f - 0.02f * static_cast<float>(i));
    }
    pixels[5] = glm::vec3(std::numeric_limits<float>::quiet_NaN(), -1.0f, 2.0f);
    for (const Transform& t : kTransforms) {
        for (std::size_t n : {std::size_t{0}, std::size_t{3}, std::size_t{8}, std::size_t{37}}) {
            const std::span<const glm::vec3> some(pixels.data(), n);
            std::vector<uint8_t> rgba(4 * n), bgra(4 * n), bgraScalar(4 * n);
            toRgba8(some, t.scale, t.mode, t.exposure, rgba);
            toRgba8(some, t.scale, t.mode, t.exposure, bgra, PixelOrder::Bgra);
            toRgba8Scalar(some, t.scale, t.mode, t.exposure, bgraScalar, PixelOrder::Bgra);
            EXPECT_EQ(bgra, bgraScalar) << t << ", " << n << " pixels";
            for (std::size_t i = 0; i < n; ++i) {
                const uint8_t* c = &rgba[4 * i];
                const uint8_t* d = &bgra[4 * i];
                ASSERT_TRUE(d[0] == c[2] && d[1] == c[1] && d[2] == c[0] && d[3] == 255)
                    << t << ", pixel " << i;
            }
        }
    }
    // Not a swap of equal bytes: the first pixel is black red, full blue.
    std::vector<uint8_t> one(4);
    toRgba8(std::span<const glm::vec3>(pixels.data(), 1), 1.0f, DisplayMode::Lab, 0.0f, one,
            PixelOrder::Bgra);
    EXPECT_EQ(one, (std::vector<uint8_t>{255, 128, 0, 255}));
}

} // namespace
} // namespace raylab
