#pragma once
// The sRGB display's 8-bit quantizer without a pow per channel: byte(x) = round(255 *
// srgbEncode(x)) for x in linear units, read from tables derived once from that formula.

#include <array>
#include <cstdint>
#include <vector>

namespace raylab {

// The sRGB transfer curve (IEC 61966-2-1) of a linear value in [0, 1].
float srgbEncode(float linear);

// round(255 * srgbEncode(x)) computed directly: 0 for x <= 0 or NaN, 255 for x >= 1.
uint8_t srgbByteByFormula(float linear);

class SrgbQuantizer {
public:
    SrgbQuantizer();

    // Equals srgbByteByFormula(linear) for every float (the formula rises monotonically; the
    // tables are its 255 steps): a table read and at most one comparison.
    uint8_t operator()(float linear) const {
        if (!(linear > 0.0f)) {
            return 0;
        }
        if (linear >= 1.0f) {
            return 255;
        }
        uint32_t bits;
        __builtin_memcpy(&bits, &linear, sizeof bits);
        unsigned byte = buckets_[bits >> kBucketShift] >> 16;
        while (byte < 255 && linear >= firstOf_[byte + 1]) {
            ++byte;
        }
        return static_cast<uint8_t>(byte);
    }

    // The smallest float whose byte is b (b >= 1).
    float firstOf(int b) const { return firstOf_[b]; }

    // Bucket k holds the floats whose bits >> kBucketShift are k; buckets 0 to kBuckets - 1 cover
    // [0, 1], the last one holding 1.0f.
    static constexpr int kBucketShift = 15; // buckets of 2^15 floats: 8 mantissa bits kept
    static constexpr uint32_t kLowBits = (1u << kBucketShift) - 1;
    static constexpr uint32_t kBuckets = (0x3f800000u >> kBucketShift) + 1;

    // One 32-bit entry per bucket, for SIMD code: bits 16-23 are the byte of the bucket's first
    // float; bits 0-15 are the low bits (bits & kLowBits) of firstOf(that byte + 1) when that
    // float lies in the bucket, otherwise kLowBits + 1. A bucket holds at most one step (checked
    // when built), so for x in [0, 1] with e = bucketTable()[bits(x) >> kBucketShift]:
    // byte(x) = (e >> 16) + ((bits(x) & kLowBits) >= (e & 0xffff) ? 1 : 0).
    const uint32_t* bucketTable() const { return buckets_.data(); }

private:
    std::array<float, 256> firstOf_{};
    std::vector<uint32_t> buckets_; // kBuckets entries, as bucketTable() describes
};

// The one quantizer every caller shares (built on first use, immutable afterwards).
const SrgbQuantizer& srgbQuantizer();

} // namespace raylab
