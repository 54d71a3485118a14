#include "render/srgb_quantizer.h"

#include <cassert>
#include <cmath>
#include <cstring>

namespace raylab {

float srgbEncode(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

uint8_t srgbByteByFormula(float linear) {
    if (!(linear > 0.0f)) {
        return 0;
    }
    const float unit = srgbEncode(linear);
    if (!(unit > 0.0f)) {
        return 0;
    }
    if (unit >= 1.0f) {
        return 255;
    }
    return static_cast<uint8_t>(unit * 255.0f + 0.5f);
}

namespace {
float floatOf(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}
uint32_t bitsOf(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}
} // namespace

SrgbQuantizer::SrgbQuantizer() {
    // Positive floats order as their bit patterns, so each step is found by bisection on bits:
    // the first float in (0, 1] whose byte reaches b.
    const uint32_t one = bitsOf(1.0f);
    firstOf_[0] = 0.0f;
    for (int b = 1; b < 256; ++b) {
        uint32_t lo = 1, hi = one; // byte(lo) < b <= byte(hi) unless lo already reaches b
        if (srgbByteByFormula(floatOf(lo)) >= b) {
            hi = lo;
        }
        while (lo < hi) {
            const uint32_t mid = lo + (hi - lo) / 2;
            if (srgbByteByFormula(floatOf(mid)) >= b) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        firstOf_[b] = floatOf(hi);
    }
    buckets_.resize(kBuckets);
    unsigned byte = 0;
    for (uint32_t k = 0; k < kBuckets; ++k) {
        const uint32_t start = k << kBucketShift;
        while (byte < 255 && floatOf(start) >= firstOf_[byte + 1]) {
            ++byte;
        }
        uint32_t step = kLowBits + 1;
        if (byte < 255 && bitsOf(firstOf_[byte + 1]) >> kBucketShift == k) {
            step = bitsOf(firstOf_[byte + 1]) & kLowBits;
            // At most one step per bucket: the next one starts in a later bucket.
            assert(byte == 254 || bitsOf(firstOf_[byte + 2]) >> kBucketShift > k);
        }
        buckets_[k] = (byte << 16) | step;
    }
    assert(buckets_[kBuckets - 1] >> 16 == 255); // 1.0f's bucket
}

const SrgbQuantizer& srgbQuantizer() {
    static const SrgbQuantizer quantizer;
    return quantizer;
}

} // namespace raylab
