#include "render/display_transform.h"

#include "bvh/bvh.h"
#include "render/false_colour.h"
#include "render/srgb_quantizer.h"
#include "watertight_avx2.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace raylab {

namespace {

// round(clamp(unit, 0, 1) * 255), NaN to 0; branch-free so the loops below vectorise.
inline uint8_t quantize(float unit) {
    const float clamped = std::min(unit > 0.0f ? unit : 0.0f, 1.0f);
    return static_cast<uint8_t>(clamped * 255.0f + 0.5f);
}

// The AVX2 path: 8 pixels (24 floats, three registers) at a time, the scalar operations in the
// same order per float (core builds with -ffp-contract=off), so the bytes are toRgba8Scalar's.
static_assert(sizeof(glm::vec3) == 3 * sizeof(float));

// max_ps(x, 0) returns its second operand when x is NaN (and for x = -0): x > 0 ? x : 0.
RAYLAB_AVX2 inline __m256 clampUnit8(__m256 x) {
    return _mm256_min_ps(_mm256_max_ps(x, _mm256_setzero_ps()), _mm256_set1_ps(1.0f));
}

RAYLAB_AVX2 inline __m256i labQuantize8(__m256 unit) {
    const __m256 scaled = _mm256_mul_ps(clampUnit8(unit), _mm256_set1_ps(255.0f));
    return _mm256_cvttps_epi32(_mm256_add_ps(scaled, _mm256_set1_ps(0.5f)));
}

// SrgbQuantizer::operator() on 8 lanes, through its bucketTable(). Clamping first sends NaN,
// x <= 0 and x >= 1 to 0 and 1, whose bytes 0 and 255 are the scalar early returns.
RAYLAB_AVX2 inline __m256i srgbQuantize8(__m256 linear, const uint32_t* buckets) {
    const __m256i bits = _mm256_castps_si256(clampUnit8(linear));
    const __m256i entry =
        _mm256_i32gather_epi32(reinterpret_cast<const int*>(buckets),
                               _mm256_srli_epi32(bits, SrgbQuantizer::kBucketShift), 4);
    const __m256i low = _mm256_and_si256(bits, _mm256_set1_epi32(SrgbQuantizer::kLowBits));
    // -1 in lanes before the bucket's step, 0 from it on: byte = (entry >> 16) + 1 + below.
    const __m256i below =
        _mm256_cmpgt_epi32(_mm256_and_si256(entry, _mm256_set1_epi32(0xffff)), low);
    return _mm256_add_epi32(_mm256_srli_epi32(entry, 16),
                            _mm256_add_epi32(below, _mm256_set1_epi32(1)));
}

// Stores 8 RGBA pixels from 24 channel bytes in 0..255 (one per int32 lane, in input order).
RAYLAB_AVX2 inline void storeRgba8(__m256i c0, __m256i c1, __m256i c2, PixelOrder order,
                                   uint8_t* out) {
    // Packing works per 128-bit half: dwords of `bytes` hold channels 0-3, 8-11, 16-19, 16-19 |
    // 4-7, 12-15, 20-23, 20-23.
    const __m256i bytes =
        _mm256_packus_epi16(_mm256_packs_epi32(c0, c1), _mm256_packs_epi32(c2, c2));
    // Channels 0-11 (pixels 0-3) to the low half, 12-23 (pixels 4-7) to the high half.
    const __m256i ordered =
        _mm256_permutevar8x32_epi32(bytes, _mm256_setr_epi32(0, 4, 1, 1, 5, 2, 6, 6));
    const __m256i spread = _mm256_shuffle_epi8(
        ordered, order == PixelOrder::Rgba
                     ? _mm256_setr_epi8(0, 1, 2, -1, 3, 4, 5, -1, 6, 7, 8, -1, 9, 10, 11, -1, //
                                        0, 1, 2, -1, 3, 4, 5, -1, 6, 7, 8, -1, 9, 10, 11, -1)
                     : _mm256_setr_epi8(2, 1, 0, -1, 5, 4, 3, -1, 8, 7, 6, -1, 11, 10, 9, -1, //
                                        2, 1, 0, -1, 5, 4, 3, -1, 8, 7, 6, -1, 11, 10, 9, -1));
    const __m256i rgba = _mm256_or_si256(spread, _mm256_set1_epi32(static_cast<int>(0xff000000u)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), rgba);
}

// Converts the first multiple of 8 pixels; returns how many.
RAYLAB_AVX2 std::size_t toRgba8Avx2(std::span<const glm::vec3> linear, float scale,
                                    DisplayMode mode, float exposure, std::span<uint8_t> rgba,
                                    PixelOrder order) {
    const std::size_t count = linear.size() & ~std::size_t{7};
    const float* in = reinterpret_cast<const float*>(linear.data());
    const __m256 scale8 = _mm256_set1_ps(scale);
    if (mode == DisplayMode::Lab) {
        for (std::size_t i = 0; i < count; i += 8, in += 24) {
            __m256i c[3];
            for (int k = 0; k < 3; ++k) {
                c[k] = labQuantize8(_mm256_mul_ps(_mm256_loadu_ps(in + 8 * k), scale8));
            }
            storeRgba8(c[0], c[1], c[2], order, &rgba[4 * i]);
        }
        return count;
    }
    const uint32_t* buckets = srgbQuantizer().bucketTable();
    const __m256 gain = _mm256_set1_ps(std::exp2(exposure));
    for (std::size_t i = 0; i < count; i += 8, in += 24) {
        __m256i c[3];
        for (int k = 0; k < 3; ++k) {
            const __m256 scaled = _mm256_mul_ps(_mm256_loadu_ps(in + 8 * k), scale8);
            c[k] = srgbQuantize8(_mm256_mul_ps(scaled, gain), buckets);
        }
        storeRgba8(c[0], c[1], c[2], order, &rgba[4 * i]);
    }
    return count;
}

} // namespace

uint8_t displayChannel(float value, DisplayMode mode, float exposure) {
    if (mode == DisplayMode::Lab) {
        return quantize(value);
    }
    if (mode == DisplayMode::FalseColour) {
        return falseColour(glm::vec3(value), exposure)[0];
    }
    return srgbQuantizer()(value * std::exp2(exposure));
}

std::array<uint8_t, 3> displayPixel(const glm::vec3& value, DisplayMode mode, float exposure) {
    uint8_t rgba[4];
    toRgba8Scalar(std::span<const glm::vec3>(&value, 1), 1.0f, mode, exposure, rgba);
    return {rgba[0], rgba[1], rgba[2]};
}

void toRgba8Scalar(std::span<const glm::vec3> linear, float scale, DisplayMode mode, float exposure,
                   std::span<uint8_t> rgba, PixelOrder order) {
    assert(rgba.size() >= 4 * linear.size());
    const std::size_t red = order == PixelOrder::Rgba ? 0 : 2;
    const std::size_t blue = 2 - red;
    const SrgbQuantizer& srgb = srgbQuantizer();
    const float gain = std::exp2(exposure);
    for (std::size_t i = 0; i < linear.size(); ++i) {
        const glm::vec3 c = linear[i] * scale;
        uint8_t* out = &rgba[4 * i];
        if (mode == DisplayMode::Lab) {
            out[red] = quantize(c.x);
            out[1] = quantize(c.y);
            out[blue] = quantize(c.z);
        } else if (mode == DisplayMode::FalseColour) {
            const std::array<uint8_t, 3> colour = falseColour(c, exposure);
            out[red] = colour[0];
            out[1] = colour[1];
            out[blue] = colour[2];
        } else {
            out[red] = srgb(c.x * gain);
            out[1] = srgb(c.y * gain);
            out[blue] = srgb(c.z * gain);
        }
        out[3] = 255;
    }
}

void toRgba8(std::span<const glm::vec3> linear, float scale, DisplayMode mode, float exposure,
             std::span<uint8_t> rgba, PixelOrder order) {
    assert(rgba.size() >= 4 * linear.size());
    static const bool simd = bvhSimdSupported();
    // False colour is a view for reading values, not a hot path: it stays scalar.
    const std::size_t done = simd && mode != DisplayMode::FalseColour
                                 ? toRgba8Avx2(linear, scale, mode, exposure, rgba, order)
                                 : 0;
    if (done < linear.size()) {
        toRgba8Scalar(linear.subspan(done), scale, mode, exposure, rgba.subspan(4 * done), order);
    }
}

std::vector<uint8_t> toRgba8(const Framebuffer& image, DisplayMode mode, float exposure) {
    std::vector<uint8_t> rgba(4 * image.pixels.size());
    toRgba8(image.pixels, 1.0f, mode, exposure, rgba);
    return rgba;
}

} // namespace raylab
