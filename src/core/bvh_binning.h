#pragma once
// The build's inner loops (internal to bvh_build.cpp), in SSE2, the x86-64 baseline: the bounds
// of a range of primitive records, and their SAH bins. One record's box is one 128-bit register.

#include "aabb.h"

#include <cstdint>
#include <emmintrin.h>

namespace raylab {

inline constexpr int kMaxBins = 32;

// A triangle as the builder moves it around: its bounds and its scene index. 32 bytes, two
// 128-bit loads (the fourth lanes hold the index bits and 0 and are ignored).
struct PrimRecord {
    glm::vec3 lower;
    uint32_t sceneIndex;
    glm::vec3 upper;
    float pad = 0.0f;
    glm::vec3 centroid() const { return lower + upper; } // twice the centre: only compared
};
static_assert(sizeof(PrimRecord) == 32);

struct SseBox {
    __m128 lower = _mm_set1_ps(kInfinity);
    __m128 upper = _mm_set1_ps(-kInfinity);
    void extend(__m128 lo, __m128 hi) {
        lower = _mm_min_ps(lower, lo);
        upper = _mm_max_ps(upper, hi);
    }
    Aabb toAabb() const {
        alignas(16) float lo[4], hi[4];
        _mm_store_ps(lo, lower);
        _mm_store_ps(hi, upper);
        return Aabb{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
    }
};

// Bounds of the boxes and of the centroids of records [first, last).
inline void boundsOf(const PrimRecord* first, const PrimRecord* last, Aabb& bounds,
                     Aabb& centroids) {
    SseBox box, centres;
    for (const PrimRecord* r = first; r != last; ++r) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        box.extend(lo, hi);
        const __m128 c = _mm_add_ps(lo, hi);
        centres.extend(c, c);
    }
    bounds = box.toAabb();
    centroids = centres.toAabb();
}

struct BinSet {
    SseBox box[3][kMaxBins];
    uint32_t count[3][kMaxBins] = {};
};

// Bin of a centroid coordinate c: floor((c - lower) * scale), clamped to [0, bins - 1]; the same
// expression as binRecords computes, so partitioning by it reproduces the bins.
inline int binOf(float c, float lower, float scale, int bins) {
    float x = (c - lower) * scale;
    x = x < 0.0f ? 0.0f : x;
    x = x > static_cast<float>(bins - 1) ? static_cast<float>(bins - 1) : x;
    return static_cast<int>(x);
}

// Bins records [first, last) on all three axes at once.
inline void binRecords(const PrimRecord* first, const PrimRecord* last, const glm::vec3& lower,
                       const glm::vec3& scale, int bins, BinSet& out) {
    const __m128 lo4 = _mm_setr_ps(lower.x, lower.y, lower.z, 0.0f);
    const __m128 scale4 = _mm_setr_ps(scale.x, scale.y, scale.z, 0.0f);
    const __m128 top = _mm_set1_ps(static_cast<float>(bins - 1));
    alignas(16) int32_t b[4];
    for (const PrimRecord* r = first; r != last; ++r) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        __m128 x = _mm_mul_ps(_mm_sub_ps(_mm_add_ps(lo, hi), lo4), scale4);
        x = _mm_min_ps(_mm_max_ps(x, _mm_setzero_ps()), top);
        _mm_store_si128(reinterpret_cast<__m128i*>(b), _mm_cvttps_epi32(x));
        for (int a = 0; a < 3; ++a) {
            out.box[a][b[a]].extend(lo, hi);
            ++out.count[a][b[a]];
        }
    }
}

} // namespace raylab
