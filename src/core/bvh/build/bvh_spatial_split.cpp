#include "bvh/build/bvh_spatial_split.h"

#include "bvh/build/bvh_build_clip.h"

#include <algorithm>
#include <array>

namespace raylab {

namespace {

// The plane between bin i - 1 and bin i (0 < i < kSpatialBins) of [lower, lower + extent];
// plane 0 is `lower` itself.
float planeOf(float lower, float extent, int i) {
    return lower + extent * (static_cast<float>(i) / static_cast<float>(kSpatialBins));
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
                SpatialBins& bins) {
    const float lower = bounds.lower[axis], extent = bounds.upper[axis] - bounds.lower[axis];
    if (!(extent > 0.0f)) {
        return; // a flat axis is never split
    }
    const float scale = static_cast<float>(kSpatialBins) / extent;
    // plane[i]: the plane between bins i - 1 and i (plane[0]: the node's lower bound), in lane
    // `axis` of a register.
    __m128 plane[kSpatialBins];
    for (int i = 0; i < kSpatialBins; ++i) {
        plane[i] = _mm_set1_ps(planeOf(lower, extent, i));
    }
    const __m128 onAxis = axisLane(axis);
    auto onPlane = [&](__m128 box, int i) { return withLane(onAxis, plane[i], box); };
    for (const PrimRecord* r = first; r != last; ++r) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        const int firstBin = binOf(r->lower[axis], lower, scale, kSpatialBins);
        const int lastBin = binOf(r->upper[axis], lower, scale, kSpatialBins);
        ++bins.entering[firstBin];
        ++bins.leaving[lastBin];
        if (firstBin == lastBin) {
            bins.box[firstBin].extend(lo, hi);
            continue;
        }
        // The reference's box cut to each bin's slab.
        bins.box[firstBin].extend(lo, onPlane(hi, firstBin + 1));
        for (int i = firstBin + 1; i < lastBin; ++i) {
            bins.box[i].extend(onPlane(lo, i), onPlane(hi, i + 1));
        }
        bins.box[lastBin].extend(onPlane(lo, lastBin), hi);
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
            best.position = planeOf(lower, extent, s);
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
