#include "bvh/build/bvh_build_object_split.h"

#include <algorithm>

namespace raylab {

namespace {

// Aabb::area() of a non-empty box: 2 (ex ey + ey ez + ez ex), rounded in that order.
float areaOf(const SseBox& b) {
    const __m128 e = _mm_sub_ps(b.upper, b.lower);
    const __m128 p = _mm_mul_ps(e, _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1)));
    const float xy = _mm_cvtss_f32(p);
    const float yz = _mm_cvtss_f32(_mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1)));
    const float zx = _mm_cvtss_f32(_mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 2, 2, 2)));
    return 2.0f * (xy + yz + zx);
}

// Bit s set for each bin s < binCount with a non-zero count.
uint32_t nonEmptyBins(const uint32_t* count, int binCount) {
    uint32_t mask = 0;
    const __m128i zero = _mm_setzero_si128();
    for (int s = 0; s < binCount; s += 4) { // kMaxBins is a multiple of 4
        const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(count + s));
        const int empty = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(c, zero)));
        mask |= static_cast<uint32_t>(~empty & 15) << s;
    }
    return binCount >= 32 ? mask : mask & ((1u << binCount) - 1);
}

} // namespace

ObjectSplit objectBinFrame(const Aabb& centroids, int bins) {
    ObjectSplit frame;
    const glm::vec3 extent = centroids.upper - centroids.lower;
    frame.lower = centroids.lower;
    for (int a = 0; a < 3; ++a) {
        // Slightly below bins/extent so the largest centroid lands in the last bin.
        frame.scale[a] = extent[a] > 0.0f ? static_cast<float>(bins) * 0.99999f / extent[a] : 0.0f;
    }
    return frame;
}

ObjectSplit bestObjectSplit(const BinSet& bins, int binCount, uint32_t count,
                            const ObjectSplit& frame) {
    ObjectSplit best = frame;
    // Sweep each axis over its non-empty bins only: a plane between two empty bins splits the
    // references as the plane right after the last non-empty bin on its left, at the same
    // cost, and that earliest plane is the one kept.
    for (int a = 0; a < 3; ++a) {
        if (!(frame.scale[a] > 0.0f)) {
            continue;
        }
        int used[kMaxBins]; // uninitialised on purpose: only [0, m) is read
        int m = 0;
        for (uint32_t mask = nonEmptyBins(bins.count[a], binCount); mask != 0; mask &= mask - 1) {
            used[m++] = __builtin_ctz(mask);
        }
        float rightCost[kMaxBins];
        __m128 rightLower[kMaxBins], rightUpper[kMaxBins];
        SseBox box;
        uint32_t n = 0;
        for (int k = m - 1; k > 0; --k) {
            box.extend(bins.box[a][used[k]].lower, bins.box[a][used[k]].upper);
            n += bins.count[a][used[k]];
            rightCost[k] = areaOf(box) * static_cast<float>(n);
            rightLower[k] = box.lower;
            rightUpper[k] = box.upper;
        }
        box = SseBox{};
        n = 0;
        for (int k = 1; k < m; ++k) {
            box.extend(bins.box[a][used[k - 1]].lower, bins.box[a][used[k - 1]].upper);
            n += bins.count[a][used[k - 1]];
            const float cost = areaOf(box) * static_cast<float>(n) + rightCost[k];
            if (n < count && cost < best.cost) {
                best.cost = cost;
                best.axis = a;
                best.bin = used[k - 1] + 1;
                best.leftCount = n;
                SseBox overlap;
                overlap.lower = _mm_max_ps(box.lower, rightLower[k]);
                overlap.upper = _mm_min_ps(box.upper, rightUpper[k]);
                best.overlapArea = overlap.toAabb().area();
            }
        }
    }
    return best;
}

uint32_t leftCountOf(const BinSet& bins, const ObjectSplit& split) {
    uint32_t n = 0;
    for (int s = 0; s < split.bin; ++s) {
        n += bins.count[split.axis][s];
    }
    return n;
}

void partitionRecords(const PrimRecord* first, const PrimRecord* last, const ObjectSplit& split,
                      int binCount, PrimRecord* left, PrimRecord* right, RecordBounds& leftBounds,
                      RecordBounds& rightBounds) {
    const int a = split.axis;
    const float lower = split.lower[a], scale = split.scale[a];
    // Without branches (the side is as good as random): the record goes where its side's
    // pointer says, and only that pointer moves on.
    for (const PrimRecord* r = first; r != last; ++r) {
        const __m128 lo = _mm_loadu_ps(&r->lower.x), hi = _mm_loadu_ps(&r->upper.x);
        const bool isLeft = binOf(r->lower[a] + r->upper[a], lower, scale, binCount) < split.bin;
        PrimRecord* to = isLeft ? left : right;
        _mm_storeu_ps(&to->lower.x, lo);
        _mm_storeu_ps(&to->upper.x, hi);
        left += isLeft ? 1 : 0;
        right += isLeft ? 0 : 1;
        (isLeft ? leftBounds : rightBounds).add(lo, hi);
    }
}

void medianOrder(PrimRecord* first, uint32_t count, const RecordBounds& bounds) {
    const Aabb centroids = bounds.centres.toAabb();
    const glm::vec3 extent = centroids.upper - centroids.lower;
    const int axis =
        extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
    if (extent[axis] > 0.0f) {
        std::nth_element(first, first + count / 2, first + count,
                         [axis](const PrimRecord& a, const PrimRecord& b) {
                             const float ca = a.centroid()[axis], cb = b.centroid()[axis];
                             return ca < cb || (ca == cb && a.sceneIndex < b.sceneIndex);
                         });
    }
}

} // namespace raylab
