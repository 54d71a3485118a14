#pragma once
// The build's inner loops (internal to bvh_build.cpp), in SSE2, the x86-64 baseline: the bounds
// of a range of primitive records, and their SAH bins. One record's box is one 128-bit register.

#include "aabb.h"
#include "sse_xyz.h"
#include "uninitialised_allocator.h"

#include <cstdint>
#include <emmintrin.h>
#include <vector>

namespace raylab {

inline constexpr int kMaxBins = 32;

// A triangle as the builder moves it around: its bounds and its scene index. 32 bytes, two
// 128-bit loads. The fourth lanes ride along in the SSE code on x, y and z and are ignored: the
// lower corner's holds the index bits, the upper corner's 0. Index bits below 2^23 are a subnormal
// float, and an operation on one takes a microcode assist on some CPUs (an AMD Zen 5 took 1.4-2.1
// times as long over a whole build), so they never enter arithmetic: see xyzOf.
struct PrimRecord {
    glm::vec3 lower;
    uint32_t sceneIndex;
    glm::vec3 upper;
    float zero;                                          // 0.0f in every record (above)
    glm::vec3 centroid() const { return lower + upper; } // twice the centre: only compared
};
static_assert(sizeof(PrimRecord) == 32);

// The build's arrays of references (resize() leaves them unwritten: the build writes every
// record it makes room for).
using RecordVector = UninitialisedVector<PrimRecord>;

// All bits set in lane `axis` (0, 1 or 2) of a register, the other lanes clear.
inline __m128 axisLane(int axis) {
    alignas(16) static constexpr uint32_t kLaneMasks[3][4] = {
        {~0u, 0, 0, 0}, {0, ~0u, 0, 0}, {0, 0, ~0u, 0}};
    return _mm_load_ps(reinterpret_cast<const float*>(kLaneMasks[axis]));
}

// `rest` with the lane that `lane` (an axisLane) selects taken from `value`.
inline __m128 withLane(__m128 lane, __m128 value, __m128 rest) {
    return _mm_or_ps(_mm_and_ps(lane, value), _mm_andnot_ps(lane, rest));
}

// Twice the centre of the box (lower, upper), a record's centroid (PrimRecord::centroid); the
// lower corner's lane 3 (index bits) cleared first, as wherever a lower corner enters arithmetic.
inline __m128 centroidOf(__m128 lower, __m128 upper) { return _mm_add_ps(xyzOf(lower), upper); }

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

// The bounds of some records' boxes and of their centroids, as the build carries them from a
// node to its children. min and max are exact, so the result does not depend on the order the
// records are added in (up to the sign of zero: merge in a fixed order).
struct RecordBounds {
    SseBox box, centres;
    void add(__m128 lo, __m128 hi) {
        box.extend(lo, hi);
        const __m128 c = centroidOf(lo, hi);
        centres.extend(c, c);
    }
    void add(const PrimRecord& r) { add(_mm_loadu_ps(&r.lower.x), _mm_loadu_ps(&r.upper.x)); }
    void merge(const RecordBounds& o) {
        box.extend(o.box.lower, o.box.upper);
        centres.extend(o.centres.lower, o.centres.upper);
    }
};

// Bounds of the boxes and of the centroids of records [first, last).
inline RecordBounds boundsOf(const PrimRecord* first, const PrimRecord* last) {
    RecordBounds b;
    for (const PrimRecord* r = first; r != last; ++r) {
        b.add(*r);
    }
    return b;
}

// SAH bins of the three axes. Only the first `bins` of each axis are used; reset() empties them.
// Cache-line aligned: the chunks of a node binned on the team fill one each, side by side.
struct alignas(64) BinSet {
    SseBox box[3][kMaxBins];
    uint32_t count[3][kMaxBins] = {};
    void reset(int bins) {
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < bins; ++b) {
                box[a][b] = SseBox{};
                count[a][b] = 0;
            }
        }
    }
    // Bit b set when bin b of the first `bins` holds references on some axis.
    uint32_t usedMask(int bins) const {
        uint32_t used = 0;
        for (int b = 0; b < bins; b += 4) { // count[][kMaxBins] holds them all
            const auto at = [&](int a) {
                return _mm_loadu_si128(reinterpret_cast<const __m128i*>(&count[a][b]));
            };
            const __m128i any = _mm_or_si128(_mm_or_si128(at(0), at(1)), at(2));
            const int empty =
                _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(any, _mm_setzero_si128())));
            used |= static_cast<uint32_t>(~empty & 15) << b;
        }
        return used & ((bins >= 32 ? 0u : 1u << bins) - 1u);
    }
    // Empties the first `bins` bins (binRecords extends a bin's box only with its count): as
    // reset(), cheaper when few are used.
    void clearUsed(int bins) {
        for (uint32_t used = usedMask(bins); used != 0; used &= used - 1) {
            const int b = __builtin_ctz(used);
            for (int a = 0; a < 3; ++a) {
                box[a][b] = SseBox{};
                count[a][b] = 0;
            }
        }
    }
    void merge(const BinSet& o, int bins) {
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < bins; ++b) {
                box[a][b].extend(o.box[a][b].lower, o.box[a][b].upper);
                count[a][b] += o.count[a][b];
            }
        }
    }
};

// Bin of a centroid coordinate c: floor((c - lower) * scale), clamped to [0, bins - 1]; the same
// expression as binRecords computes, so partitioning by it reproduces the bins.
inline int binOf(float c, float lower, float scale, int bins) {
    float x = (c - lower) * scale;
    x = x < 0.0f ? 0.0f : x;
    x = x > static_cast<float>(bins - 1) ? static_cast<float>(bins - 1) : x;
    return static_cast<int>(x);
}

// binOf in the lanes of one register: lower, scale and top (bins - 1) broadcast or per lane.
// The same operations, so the same bins.
inline __m128i binOfLanes(__m128 c, __m128 lower, __m128 scale, __m128 top) {
    const __m128 x = _mm_mul_ps(_mm_sub_ps(c, lower), scale);
    return _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(x, _mm_setzero_ps()), top));
}

// binOf(c, lower, scale, bins) < bin, for 0 < bin < bins, without the clamps: below 0 binOf
// clamps to bin 0, above bins - 1 to bins - 1 >= bin, and between it truncates. The partition
// (bvh_build_object_split.cpp) sorts records by it, in SSE lanes too.
inline bool binIsBelow(float c, float lower, float scale, int bin) {
    return (c - lower) * scale < static_cast<float>(bin);
}

// One axis of a pair of records in binRecords: record 0 (lo, hi) in bin b, record 1 (lo1, hi1)
// in bin c, `same` all ones in lane `axis` where b == c, (unionLo, unionHi) the pair's box. Both
// bins are read before either is written, bin c first and bin b last, so that where b == c the
// last write holds the pair's union and a count of two. No branch on b == c: whether
// neighbours share a bin is hard to predict, and a bin's update waits for its previous one
// anyway. The same boxes, bit for bit, as adding the records one at a time.
template <int axis>
inline void binPair(BinSet& out, int b, int c, __m128 same, __m128 lo, __m128 hi, __m128 lo1,
                    __m128 hi1, __m128 unionLo, __m128 unionHi) {
    const __m128 shared = _mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(same), axis * 0x55));
    const __m128 firstLo = _mm_or_ps(_mm_and_ps(shared, unionLo), _mm_andnot_ps(shared, lo));
    const __m128 firstHi = _mm_or_ps(_mm_and_ps(shared, unionHi), _mm_andnot_ps(shared, hi));
    SseBox& boxB = out.box[axis][b];
    SseBox& boxC = out.box[axis][c];
    const __m128 lowerB = boxB.lower, upperB = boxB.upper;
    const __m128 lowerC = boxC.lower, upperC = boxC.upper;
    const uint32_t countB = out.count[axis][b], countC = out.count[axis][c];
    boxC.lower = _mm_min_ps(lowerC, lo1);
    boxC.upper = _mm_max_ps(upperC, hi1);
    out.count[axis][c] = countC + 1;
    boxB.lower = _mm_min_ps(lowerB, firstLo);
    boxB.upper = _mm_max_ps(upperB, firstHi);
    out.count[axis][b] = countB + 1 + static_cast<uint32_t>(b == c);
}

// Bins records [first, last) on all three axes at once, adding to what `out` holds, two records
// at a time (binPair).
inline void binRecords(const PrimRecord* first, const PrimRecord* last, const glm::vec3& lower,
                       const glm::vec3& scale, int bins, BinSet& out) {
    const __m128 lo4 = _mm_setr_ps(lower.x, lower.y, lower.z, 0.0f);
    const __m128 scale4 = _mm_setr_ps(scale.x, scale.y, scale.z, 0.0f);
    const __m128 top = _mm_set1_ps(static_cast<float>(bins - 1));
    auto binOf4 = [&](__m128 lo, __m128 hi) {
        return binOfLanes(centroidOf(lo, hi), lo4, scale4, top);
    };
    alignas(16) int32_t b[4], c[4];
    const PrimRecord* r = first;
    for (; last - r >= 2; r += 2) {
        const __m128 lo = _mm_loadu_ps(&r[0].lower.x), hi = _mm_loadu_ps(&r[0].upper.x);
        const __m128 lo1 = _mm_loadu_ps(&r[1].lower.x), hi1 = _mm_loadu_ps(&r[1].upper.x);
        const __m128i bin0 = binOf4(lo, hi), bin1 = binOf4(lo1, hi1);
        _mm_store_si128(reinterpret_cast<__m128i*>(b), bin0);
        _mm_store_si128(reinterpret_cast<__m128i*>(c), bin1);
        const __m128 same = _mm_castsi128_ps(_mm_cmpeq_epi32(bin0, bin1));
        const __m128 unionLo = _mm_min_ps(lo, lo1), unionHi = _mm_max_ps(hi, hi1);
        binPair<0>(out, b[0], c[0], same, lo, hi, lo1, hi1, unionLo, unionHi);
        binPair<1>(out, b[1], c[1], same, lo, hi, lo1, hi1, unionLo, unionHi);
        binPair<2>(out, b[2], c[2], same, lo, hi, lo1, hi1, unionLo, unionHi);
    }
    if (r != last) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        _mm_store_si128(reinterpret_cast<__m128i*>(b), binOf4(lo, hi));
        for (int a = 0; a < 3; ++a) {
            out.box[a][b[a]].extend(lo, hi);
            ++out.count[a][b[a]];
        }
    }
}

} // namespace raylab
