#pragma once
// Deterministic per-(pixel, sample) random numbers: a counter-based hash, no shared generator.

#include <cstdint>

namespace raylab {

// A well-mixed 32-bit hash of 32-bit input (lowbias32, a two-round xorshift-multiply).
constexpr uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// A float in [0, 1) from 24 random bits.
constexpr float unitFloat(uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1.0p-24f; }

// The sub-pixel offset of sample `sampleIndex` of pixel (x, y), each coordinate in [0, 1).
// Sample 0 is the pixel's centre (0.5, 0.5): the lab's ray.
struct PixelOffset {
    float dx, dy;
};
constexpr PixelOffset samplePixelOffset(uint32_t x, uint32_t y, uint32_t sampleIndex) {
    if (sampleIndex == 0) {
        return {0.5f, 0.5f};
    }
    const uint32_t seed = hash32(x ^ hash32(y ^ hash32(sampleIndex)));
    return {unitFloat(seed), unitFloat(hash32(seed ^ 0x9e3779b9U))};
}

} // namespace raylab
