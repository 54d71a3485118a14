#include "bvh/build/bvh_spatial_split.h"

#include "bvh/build/bvh_build_clip.h"
#include "bvh/build/bvh_clip.h"

#include <algorithm>
#include <array>

namespace raylab {

namespace {

__m128 toSse(const glm::vec3& v) { return _mm_setr_ps(v.x, v.y, v.z, 0.0f); }

// The plane between bin i - 1 and bin i (0 < i < kSpatialBins) of [lower, lower + extent].
float planeOf(float lower, float extent, int i) {
    return lower + extent * (static_cast<float>(i) / static_cast<float>(kSpatialBins));
}

} // namespace

void SpatialBins::merge(const SpatialBins& other) {
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < kSpatialBins; ++b) {
            box[a][b].extend(other.box[a][b].lower, other.box[a][b].upper);
            entering[a][b] += other.entering[a][b];
            leaving[a][b] += other.leaving[a][b];
        }
    }
}

void binSpatial(const Scene& scene, const PrimRecord* first, const PrimRecord* last,
                const Aabb& bounds, float slack, SpatialBins& bins) {
    const glm::vec3 extent = bounds.extent();
    // The bin of coordinate x is (x - lower) * scale clamped to [0, kSpatialBins - 1], with
    // scale = kSpatialBins / extent (0 on a flat axis, which is never split).
    glm::vec3 scale{0.0f};
    for (int a = 0; a < 3; ++a) {
        scale[a] = extent[a] > 0.0f ? static_cast<float>(kSpatialBins) / extent[a] : 0.0f;
    }
    const __m128 lower4 = toSse(bounds.lower), scale4 = toSse(scale);
    const __m128 top = _mm_set1_ps(static_cast<float>(kSpatialBins - 1));
    alignas(16) int32_t lowBin[4], highBin[4];
    for (const PrimRecord* r = first; r != last; ++r) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        const __m128 bl = _mm_mul_ps(_mm_sub_ps(lo, lower4), scale4);
        const __m128 bh = _mm_mul_ps(_mm_sub_ps(hi, lower4), scale4);
        _mm_store_si128(reinterpret_cast<__m128i*>(lowBin),
                        _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(bl, _mm_setzero_ps()), top)));
        _mm_store_si128(reinterpret_cast<__m128i*>(highBin),
                        _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(bh, _mm_setzero_ps()), top)));
        for (int a = 0; a < 3; ++a) {
            const int firstBin = lowBin[a], lastBin = highBin[a];
            ++bins.entering[a][firstBin];
            ++bins.leaving[a][lastBin];
            if (firstBin == lastBin) {
                bins.box[a][firstBin].extend(lo, hi);
                continue;
            }
            // Clip the triangle bin by bin: the part left of each plane goes to that bin.
            const Triangle& t = scene.triangles[r->sceneIndex];
            SseBox rest;
            rest.lower = lo;
            rest.upper = hi;
            for (int i = firstBin; i < lastBin && !isEmpty(rest); ++i) {
                SseBox left, right;
                splitBoxSse(t, rest, a, planeOf(bounds.lower[a], extent[a], i + 1), slack, left,
                            right);
                if (!isEmpty(left)) {
                    bins.box[a][i].extend(left.lower, left.upper);
                }
                rest = right;
            }
            if (!isEmpty(rest)) {
                bins.box[a][lastBin].extend(rest.lower, rest.upper);
            }
        }
    }
}

SpatialSplit bestSpatialSplit(const SpatialBins& bins, const Aabb& bounds) {
    SpatialSplit best;
    const glm::vec3 extent = bounds.extent();
    for (int a = 0; a < 3; ++a) {
        if (!(extent[a] > 0.0f)) {
            continue;
        }
        // Sweep: right side from the top, then left side from the bottom.
        std::array<float, kSpatialBins> rightCost{};
        std::array<uint32_t, kSpatialBins> rightCount{};
        Aabb acc;
        uint32_t n = 0;
        for (int s = kSpatialBins - 1; s > 0; --s) {
            acc.extend(bins.box[a][s].toAabb());
            n += bins.leaving[a][s];
            rightCost[s] = acc.area() * static_cast<float>(n);
            rightCount[s] = n;
        }
        acc = Aabb{};
        n = 0;
        for (int s = 1; s < kSpatialBins; ++s) {
            acc.extend(bins.box[a][s - 1].toAabb());
            n += bins.entering[a][s - 1];
            if (n == 0 || rightCount[s] == 0) {
                continue;
            }
            const float cost = acc.area() * static_cast<float>(n) + rightCost[s];
            if (cost < best.cost) {
                best.axis = a;
                best.position = planeOf(bounds.lower[a], extent[a], s);
                best.cost = cost;
                best.references = n + rightCount[s];
            }
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
