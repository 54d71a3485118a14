#include "bvh/build/bvh_spatial_split.h"

#include "bvh/build/bvh_build_clip.h"

#include <algorithm>
#include <array>
#include <bit>

namespace raylab {

namespace {

// Levels of the ranges of 2^k bins in binSpatial, k = 0 .. log2(kSpatialBins).
constexpr int kSpatialRangeLevels = std::bit_width(static_cast<unsigned>(kSpatialBins));

} // namespace

void SpatialBins::merge(const SpatialBins& other) {
    for (int b = 0; b < kSpatialBins; ++b) {
        box[b].extend(other.box[b].lower, other.box[b].upper);
        entering[b] += other.entering[b];
        leaving[b] += other.leaving[b];
    }
}

void binSpatial(const PrimRecord* first, const PrimRecord* last, const Aabb& bounds, int axis,
                SpatialBins& bins) {
    const float lower = bounds.lower[axis], extent = bounds.upper[axis] - bounds.lower[axis];
    if (!(extent > 0.0f)) {
        return; // a flat axis is never split
    }
    const float scale = static_cast<float>(kSpatialBins) / extent;
    // A reference covering bins [f, l] is added whole to two ranges of 2^k bins that together
    // cover them exactly, k = floor(log2(l - f + 1)): ranges[k][f] and ranges[k][l + 1 - 2^k].
    // A fixed amount of work a reference, however many bins it crosses, and no branch on it.
    SseBox ranges[kSpatialRangeLevels][kSpatialBins];
    int levelsUsed = 0;
    for (const PrimRecord* r = first; r != last; ++r) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        const int firstBin = binOf(r->lower[axis], lower, scale, kSpatialBins);
        const int lastBin = binOf(r->upper[axis], lower, scale, kSpatialBins);
        ++bins.entering[firstBin];
        ++bins.leaving[lastBin];
        const int level = std::bit_width(static_cast<unsigned>(lastBin - firstBin + 1)) - 1;
        levelsUsed |= 1 << level;
        ranges[level][firstBin].extend(lo, hi);
        ranges[level][lastBin + 1 - (1 << level)].extend(lo, hi);
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

void applySpatialSplit(const Scene& scene, const PrimRecord* first, const PrimRecord* last,
                       const SpatialSplit& split, float slack, RecordVector& left,
                       RecordVector& right, RecordBounds& leftBounds, RecordBounds& rightBounds) {
    const int a = split.axis;
    for (const PrimRecord* r = first; r != last; ++r) {
        if (r->upper[a] <= split.position) {
            left.push_back(*r);
            leftBounds.add(*r);
        } else if (r->lower[a] >= split.position) {
            right.push_back(*r);
            rightBounds.add(*r);
        } else {
            SseBox box, l, rr;
            box.lower = _mm_loadu_ps(&r->lower.x);
            box.upper = _mm_loadu_ps(&r->upper.x);
            splitBoxSse(scene.triangles[r->sceneIndex], box, a, split.position, slack, l, rr);
            if (!isEmpty(l)) {
                const Aabb part = l.toAabb();
                left.push_back({part.lower, r->sceneIndex, part.upper, 0.0f});
                leftBounds.add(left.back());
            }
            if (!isEmpty(rr)) {
                const Aabb part = rr.toAabb();
                right.push_back({part.lower, r->sceneIndex, part.upper, 0.0f});
                rightBounds.add(right.back());
            }
            if (isEmpty(l) && isEmpty(rr)) { // only if rounding lost the part: keep it whole
                left.push_back(*r);
                leftBounds.add(*r);
            }
        }
    }
}

} // namespace raylab
