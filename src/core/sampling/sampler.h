#pragma once
// The random numbers of one sample of one pixel, deterministic per (pixel, sample index,
// dimension): the same settings give the same numbers on any thread count and in any order of
// passes, and sample ranges of one render are disjoint sets of the same samples.
//
// Dimensions come in pairs (get2D(pair)); each pair of each pixel is its own Owen-scrambled Sobol
// pattern (sobol.h), so the first 2^k samples of any pair are stratified ("padded" 2D Sobol, as
// pbrt-v4's PaddedSobolSampler). Independent draws the same numbers from a hash alone (white
// noise): the baseline the Sobol points are measured against (PERFORMANCE.md).

#include "sampling/hash.h"
#include "sampling/sobol.h"

#include <cstdint>
#include <glm/vec2.hpp>

namespace raylab {

enum class SamplerKind {
    Sobol,       // Owen-scrambled Sobol, padded per dimension pair (the default)
    Independent, // a hash per (pixel, sample, dimension): white noise
};

const char* toString(SamplerKind kind);
// Parses "sobol" or "independent"; returns false for anything else.
bool parseSamplerKind(const char* text, SamplerKind& kind);

class PixelSampler {
public:
    // pixelIndex: y * width + x; seed: 0 for renders (tests vary it to draw independent runs).
    PixelSampler(SamplerKind kind, uint32_t pixelIndex, uint32_t sampleIndex, uint32_t seed = 0)
        : kind_(kind), pixelKey_(hash32(pixelIndex ^ hash32(seed + 0x68e31da4U))),
          sampleIndex_(sampleIndex), reversedIndex_(reverseBits(sampleIndex)) {}

    // A point in [0, 1)^2 of dimension pair `pair`.
    glm::vec2 get2D(uint32_t pair) const {
        const uint32_t key = hash32(pixelKey_ ^ hash32(pair * 0x9e3779b9U + 0x7f4a7c15U));
        if (kind_ == SamplerKind::Independent) {
            const uint32_t a = hash32(key ^ hash32(sampleIndex_ + 0x1b873593U));
            return glm::vec2(toUnit(a), toUnit(hash32(a ^ 0x85ebca6bU)));
        }
        // owenScramble(sobolDimension_d(owenScramble(sampleIndex, key)), seed_d), with the
        // reversals that cancel left out: the index's scramble leaves it reversed (scrambled),
        // dimension 0 of an index is its reversal, and dimension 1 is tabulated reversed.
        const uint32_t index = reverseBits(lowToHighPermutation(reversedIndex_, key));
        const uint32_t x = reverseBits(lowToHighPermutation(index, hash32(key ^ 0xa511e9b3U)));
        const uint32_t y = reverseBits(
            lowToHighPermutation(reversedSobolDimension1(index), hash32(key ^ 0x63d83595U)));
        return glm::vec2(toUnit(x), toUnit(y));
    }

    uint32_t sampleIndex() const { return sampleIndex_; }

private:
    // The top 24 bits as a float in [0, 1): exact, and never 1.
    static float toUnit(uint32_t bits) { return unitFloat(bits); }

    SamplerKind kind_;
    uint32_t pixelKey_;
    uint32_t sampleIndex_;
    uint32_t reversedIndex_;
};

} // namespace raylab
