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
        unsigned byte = bucketStart_[bits >> kBucketShift];
        while (byte < 255 && linear >= firstOf_[byte + 1]) {
            ++byte;
        }
        return static_cast<uint8_t>(byte);
    }

    // The smallest float whose byte is b (b >= 1).
    float firstOf(int b) const { return firstOf_[b]; }

private:
    static constexpr int kBucketShift = 15; // buckets of 2^15 floats: 8 mantissa bits kept
    std::array<float, 256> firstOf_{};
    std::vector<uint8_t> bucketStart_; // the byte of each bucket's first float in (0, 1)
};

// The one quantizer every caller shares (built on first use, immutable afterwards).
const SrgbQuantizer& srgbQuantizer();

} // namespace raylab
