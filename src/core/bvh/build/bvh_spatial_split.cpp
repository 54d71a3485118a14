#include "bvh/build/bvh_spatial_split.h"

#include "bvh/build/bvh_build_clip.h"

#include <algorithm>
#include <array>
#include <bit>

namespace raylab {

namespace {

// Levels of the ranges of 2^k bins in binSpatial, k = 0 .. log2(kSpatialBins).
constexpr int kSpatialRangeLevels = std::bit_width(static_cast<unsigned>(kSpatialBins));

// binSpatial's pass over the references on one axis: counts each reference entering and leaving
// and adds it to its ranges; returns bit k set where a reference went to ranges[k]. The bins of
// two references come from one SSE register holding their bounds on the axis.
template <int axis>
int addToRanges(const PrimRecord* first, std::size_t count, std::size_t stride, float lower,
                float scale, SseBox (&ranges)[kSpatialRangeLevels][kSpatialBins],
                SpatialBins& bins) {
    const __m128 lower4 = _mm_set1_ps(lower), scale4 = _mm_set1_ps(scale);
    const __m128 top = _mm_set1_ps(static_cast<float>(kSpatialBins - 1));
    // The reference's bounds on the axis in lanes 0 (lower) and 1 (upper) for axes 0 and 2, in
    // lanes 2 and 3 for axis 1.
    const auto ends = [](__m128 lo, __m128 hi) {
        return axis == 2 ? _mm_unpackhi_ps(lo, hi) : _mm_unpacklo_ps(lo, hi);
    };
    // Those bounds' bins.
    const auto binsOf = [&](__m128 x) { return binOfLanes(x, lower4, scale4, top); };
    int levelsUsed = 0;
    const auto add = [&](__m128 lo, __m128 hi, int firstBin, int lastBin) {
        ++bins.entering[firstBin];
        ++bins.leaving[lastBin];
        if (firstBin == lastBin) { // most references, in the nodes where spatial splits are tried
            levelsUsed |= 1;
            ranges[0][firstBin].extend(lo, hi);
            return;
        }
        const int level = std::bit_width(static_cast<unsigned>(lastBin - firstBin + 1)) - 1;
        levelsUsed |= 1 << level;
        ranges[level][firstBin].extend(lo, hi);
        ranges[level][lastBin + 1 - (1 << level)].extend(lo, hi);
    };
    alignas(16) int32_t bin[4];
    const PrimRecord* r = first;
    for (std::size_t k = 0; k + 2 <= count; k += 2, r += 2 * stride) { // two at once
        const __m128 lo0 = _mm_loadu_ps(&r->lower.x), hi0 = _mm_loadu_ps(&r->upper.x);
        const __m128 lo1 = _mm_loadu_ps(&r[stride].lower.x);
        const __m128 hi1 = _mm_loadu_ps(&r[stride].upper.x);
        const __m128 ends0 = ends(lo0, hi0), ends1 = ends(lo1, hi1);
        const __m128 both = axis == 1 ? _mm_movehl_ps(ends1, ends0) : _mm_movelh_ps(ends0, ends1);
        _mm_store_si128(reinterpret_cast<__m128i*>(bin), binsOf(both));
        add(lo0, hi0, bin[0], bin[1]);
        add(lo1, hi1, bin[2], bin[3]);
    }
    if (count % 2 != 0) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        const __m128 e = ends(lo, hi);
        _mm_store_si128(reinterpret_cast<__m128i*>(bin),
                        binsOf(axis == 1 ? _mm_movehl_ps(e, e) : e));
        add(lo, hi, bin[0], bin[1]);
    }
    return levelsUsed;
}

struct CrossingParts {
    SseBox left, right;
    bool leftEmpty = true, rightEmpty = true;
};

// The parts on each side of the plane x[a] = position of a reference (box lo, hi) of triangle t
// that crosses it (splitBoxSse). Out of line: inlined into applySpatialSplit, its registers
// pushed the sides' bounds out of registers, to the stack, in the loop over every reference,
// though most do not cross (Sponza's build spent 28% less in applySpatialSplit and this
// together; the same trees).
[[gnu::noinline]] CrossingParts cutCrossing(const Triangle& t, __m128 lo, __m128 hi, int a,
                                            float position, float slack) {
    CrossingParts parts;
    SseBox box;
    box.lower = lo;
    box.upper = hi;
    splitBoxSse(t, box, a, position, slack, parts.left, parts.right);
    parts.leftEmpty = isEmpty(parts.left);
    parts.rightEmpty = isEmpty(parts.right);
    return parts;
}

} // namespace

void SpatialBins::merge(const SpatialBins& other) {
    for (int b = 0; b < kSpatialBins; ++b) {
        box[b].extend(other.box[b].lower, other.box[b].upper);
        entering[b] += other.entering[b];
        leaving[b] += other.leaving[b];
    }
}

void binSpatial(const PrimRecord* first, const PrimRecord* last, const Aabb& bounds, int axis,
                SpatialBins& bins, std::size_t stride) {
    const float lower = bounds.lower[axis], extent = bounds.upper[axis] - bounds.lower[axis];
    if (!(extent > 0.0f)) {
        return; // a flat axis is never split
    }
    const float scale = static_cast<float>(kSpatialBins) / extent;
    // A reference covering bins [f, l] is added whole to two ranges of 2^k bins that together
    // cover them exactly, k = floor(log2(l - f + 1)): ranges[k][f] and ranges[k][l + 1 - 2^k].
    // A fixed amount of work a reference, however many bins it crosses.
    SseBox ranges[kSpatialRangeLevels][kSpatialBins];
    int levelsUsed = 0;
    const std::size_t count =
        first < last ? (static_cast<std::size_t>(last - first) + stride - 1) / stride : 0;
    switch (axis) {
    case 0: levelsUsed = addToRanges<0>(first, count, stride, lower, scale, ranges, bins); break;
    case 1: levelsUsed = addToRanges<1>(first, count, stride, lower, scale, ranges, bins); break;
    default: levelsUsed = addToRanges<2>(first, count, stride, lower, scale, ranges, bins); break;
    }
    // Each range handed down to its two halves, so that ranges[0][i] is the union of the whole
    // boxes of the references crossing bin i.
    for (int level = std::bit_width(static_cast<unsigned>(levelsUsed)) - 1; level > 0; --level) {
        const int half = 1 << (level - 1);
        for (int p = 0; p + (1 << level) <= kSpatialBins; ++p) {
            const SseBox& range = ranges[level][p];
            ranges[level - 1][p].extend(range.lower, range.upper);
            ranges[level - 1][p + half].extend(range.lower, range.upper);
        }
    }
    // That union cut to the bin's slab is the union of the references' parts in the slab
    // (taking bounds to the slab commutes with min and max). The outer bins' slabs are open,
    // so a reference that rounding places in them is not cut by the node's own bounds.
    const __m128 onAxis = axisLane(axis);
    for (int i = 0; i < kSpatialBins; ++i) {
        const float below = i == 0 ? -kInfinity : spatialPlane(lower, extent, i);
        const float above = i == kSpatialBins - 1 ? kInfinity : spatialPlane(lower, extent, i + 1);
        const __m128 slabLower = withLane(onAxis, _mm_set1_ps(below), _mm_set1_ps(-kInfinity));
        const __m128 slabUpper = withLane(onAxis, _mm_set1_ps(above), _mm_set1_ps(kInfinity));
        const SseBox& crossing = ranges[0][i];
        bins.box[i].extend(_mm_max_ps(crossing.lower, slabLower),
                           _mm_min_ps(crossing.upper, slabUpper));
    }
}

SpatialSplit bestSpatialSplit(const SpatialBins& bins, const Aabb& bounds, int axis) {
    SpatialSplit best;
    const float lower = bounds.lower[axis], extent = bounds.upper[axis] - bounds.lower[axis];
    if (!(extent > 0.0f)) {
        return best;
    }
    // Sweep: right side from the top, then left side from the bottom.
    std::array<float, kSpatialBins> rightCost{};
    std::array<uint32_t, kSpatialBins> rightCount{};
    Aabb acc;
    uint32_t n = 0;
    for (int s = kSpatialBins - 1; s > 0; --s) {
        acc.extend(bins.box[s].toAabb());
        n += bins.leaving[s];
        rightCost[s] = acc.area() * static_cast<float>(n);
        rightCount[s] = n;
    }
    acc = Aabb{};
    n = 0;
    for (int s = 1; s < kSpatialBins; ++s) {
        acc.extend(bins.box[s - 1].toAabb());
        n += bins.entering[s - 1];
        if (n == 0 || rightCount[s] == 0) {
            continue;
        }
        const float cost = acc.area() * static_cast<float>(n) + rightCost[s];
        if (cost < best.cost) {
            best.axis = axis;
            best.position = spatialPlane(lower, extent, s);
            best.cost = cost;
            best.references = n + rightCount[s];
        }
    }
    return best;
}

namespace {

// Where spatialSides writes: the sides to arrays of their own (applySpatialSplit), nowhere
// (countSpatialSplit), or into one room, the right side down from its end
// (applySpatialSplitInRoom).
enum class SidesTo { Arrays, Nowhere, OneRoom };

// applySpatialSplit, countSpatialSplit or applySpatialSplitInRoom (with `right` the room's end):
// the same decisions each way.
template <SidesTo kTo>
SpatialSides spatialSides(const Scene& scene, const PrimRecord* first, const PrimRecord* last,
                          const SpatialSplit& split, float slack, PrimRecord* left,
                          PrimRecord* right, RecordBounds& leftBounds, RecordBounds& rightBounds) {
    const int a = split.axis;
    // The sides' ends and bounds are kept in registers, stored once.
    std::size_t l = 0, r = 0;
    RecordBounds lb = leftBounds, rb = rightBounds;
    const auto store = [](PrimRecord* to, __m128 lo, __m128 hi) {
        _mm_storeu_ps(&to->lower.x, lo);
        _mm_storeu_ps(&to->upper.x, hi);
    };
    const auto putLeft = [&](__m128 lo, __m128 hi) {
        if constexpr (kTo != SidesTo::Nowhere) {
            store(left + l, lo, hi);
        }
        ++l;
        lb.add(lo, hi);
    };
    const auto putRight = [&](__m128 lo, __m128 hi) {
        if constexpr (kTo == SidesTo::Arrays) {
            store(right + r, lo, hi);
        } else if constexpr (kTo == SidesTo::OneRoom) {
            store(right - 1 - r, lo, hi);
        }
        ++r;
        rb.add(lo, hi);
    };
    // Lane 3 of a record's lower corner holds its scene index: a part keeps the reference's
    // (and takes PrimRecord::zero in its upper corner's).
    const __m128 indexLane = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, -1));
    for (const PrimRecord* p = first; p != last; ++p) {
        const __m128 lo = _mm_loadu_ps(&p->lower.x), hi = _mm_loadu_ps(&p->upper.x);
        if (p->upper[a] <= split.position) {
            putLeft(lo, hi);
        } else if (p->lower[a] >= split.position) {
            putRight(lo, hi);
        } else {
            const CrossingParts parts =
                cutCrossing(scene.triangles[p->sceneIndex], lo, hi, a, split.position, slack);
            if (!parts.leftEmpty) {
                putLeft(withLane(indexLane, lo, parts.left.lower), xyzOf(parts.left.upper));
            }
            if (!parts.rightEmpty) {
                putRight(withLane(indexLane, lo, parts.right.lower), xyzOf(parts.right.upper));
            }
            if (parts.leftEmpty && parts.rightEmpty) {
                putLeft(lo, hi); // only if rounding lost the part: keep it whole
            }
        }
    }
    leftBounds = lb;
    rightBounds = rb;
    return {l, r};
}

} // namespace

SpatialSides applySpatialSplit(const Scene& scene, const PrimRecord* first, const PrimRecord* last,
                               const SpatialSplit& split, float slack, PrimRecord* left,
                               PrimRecord* right, RecordBounds& leftBounds,
                               RecordBounds& rightBounds) {
    return spatialSides<SidesTo::Arrays>(scene, first, last, split, slack, left, right, leftBounds,
                                         rightBounds);
}

SpatialSides applySpatialSplitInRoom(const Scene& scene, const PrimRecord* first,
                                     const PrimRecord* last, const SpatialSplit& split, float slack,
                                     PrimRecord* room, std::size_t roomSize,
                                     RecordBounds& leftBounds, RecordBounds& rightBounds) {
    const SpatialSides made = spatialSides<SidesTo::OneRoom>(
        scene, first, last, split, slack, room, room + roomSize, leftBounds, rightBounds);
    if (made.left + made.right <= roomSize) {
        std::reverse(room + (roomSize - made.right), room + roomSize);
    }
    return made;
}

SpatialSides countSpatialSplit(const Scene& scene, const PrimRecord* first, const PrimRecord* last,
                               const SpatialSplit& split, float slack, RecordBounds& leftBounds,
                               RecordBounds& rightBounds) {
    return spatialSides<SidesTo::Nowhere>(scene, first, last, split, slack, nullptr, nullptr,
                                          leftBounds, rightBounds);
}

} // namespace raylab
