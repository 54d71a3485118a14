#include "bvh/build/bvh_build_object_split.h"

#include <algorithm>

namespace raylab {

namespace {

// Lanes of b where mask is set, of a elsewhere (SSE2 has no blend).
__m128 select(__m128 mask, __m128 a, __m128 b) {
    return _mm_or_ps(_mm_andnot_ps(mask, a), _mm_and_ps(mask, b));
}

// The boxes of the three axes' sides at one plane: box a is axis a's.
struct AxisBoxes {
    __m128 lower[3] = {_mm_set1_ps(kInfinity), _mm_set1_ps(kInfinity), _mm_set1_ps(kInfinity)};
    __m128 upper[3] = {_mm_set1_ps(-kInfinity), _mm_set1_ps(-kInfinity), _mm_set1_ps(-kInfinity)};
    void extend(const BinSet& bins, int bin) {
        for (int a = 0; a < 3; ++a) {
            lower[a] = _mm_min_ps(lower[a], bins.box[a][bin].lower);
            upper[a] = _mm_max_ps(upper[a], bins.box[a][bin].upper);
        }
    }
    // Lane a: Aabb::area() of box a, 2 (ex ey + ey ez + ez ex) rounded in that order (infinite
    // or NaN for an empty box).
    __m128 areas() const {
        const __m128 a = _mm_sub_ps(upper[0], xyzOf(lower[0]));
        const __m128 b = _mm_sub_ps(upper[1], xyzOf(lower[1]));
        const __m128 c = _mm_sub_ps(upper[2], xyzOf(lower[2]));
        // The extents transposed: x = (a.x, b.x, c.x), y, z alike. Lane 3 (not used) takes
        // one of c's extents.
        const __m128 ab01 = _mm_unpacklo_ps(a, b), ab23 = _mm_unpackhi_ps(a, b);
        const __m128 x = _mm_movelh_ps(ab01, c);
        const __m128 y = _mm_shuffle_ps(ab01, c, _MM_SHUFFLE(1, 1, 3, 2));
        const __m128 z = _mm_shuffle_ps(ab23, c, _MM_SHUFFLE(2, 2, 1, 0));
        const __m128 sum =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, y), _mm_mul_ps(y, z)), _mm_mul_ps(z, x));
        return _mm_mul_ps(_mm_set1_ps(2.0f), sum);
    }
};

__m128i countsOf(const BinSet& bins, int bin) {
    return _mm_setr_epi32(static_cast<int>(bins.count[0][bin]),
                          static_cast<int>(bins.count[1][bin]),
                          static_cast<int>(bins.count[2][bin]), 0);
}

} // namespace

ObjectSplit objectBinFrame(const Aabb& centroids, int bins) {
    ObjectSplit frame;
    const glm::vec3 extent = centroids.upper - centroids.lower;
    frame.lower = centroids.lower;
    frame.bins = bins;
    for (int a = 0; a < 3; ++a) {
        // Slightly below bins/extent so the largest centroid lands in the last bin.
        frame.scale[a] = extent[a] > 0.0f ? static_cast<float>(bins) * 0.99999f / extent[a] : 0.0f;
    }
    return frame;
}

ObjectSplit bestObjectSplit(const BinSet& bins, uint32_t count, const ObjectSplit& frame) {
    const int binCount = frame.bins;
    // The three axes are swept at once, one SSE lane each. Plane k lies between bins k - 1 and
    // k. A plane next to an empty bin splits the references as its neighbour does, at the same
    // cost; the earliest plane of the cheapest cost is kept, on the lowest such axis. So only
    // the planes just after a bin used on some axis are costed (the others cost exactly what
    // the plane before them does, with the same boxes and counts), and only used bins swept:
    // a small node uses few of its bins.
    int used[kMaxBins]; // the used bins, in increasing order
    int usedCount = 0;
    for (uint32_t mask = bins.usedMask(binCount); mask != 0; mask &= mask - 1) {
        used[usedCount++] = __builtin_ctz(mask);
    }
    // rightCost[j]: the cost of the side right of plane used[j - 1] + 1, bins used[j] on.
    float rightCost[kMaxBins][4];
    AxisBoxes side;
    __m128i n = _mm_setzero_si128();
    for (int j = usedCount - 1; j > 0; --j) {
        side.extend(bins, used[j]);
        n = _mm_add_epi32(n, countsOf(bins, used[j]));
        _mm_storeu_ps(rightCost[j], _mm_mul_ps(side.areas(), _mm_cvtepi32_ps(n)));
    }
    const __m128i all = _mm_set1_epi32(static_cast<int>(count));
    const __m128 splittable = _mm_cmpgt_ps(
        _mm_setr_ps(frame.scale.x, frame.scale.y, frame.scale.z, 0.0f), _mm_setzero_ps());
    __m128 bestCost = _mm_set1_ps(kInfinity);
    __m128i bestPlane = _mm_setzero_si128();
    side = AxisBoxes{};
    n = _mm_setzero_si128();
    // A plane after the last used bin has nothing on its right: never a split.
    for (int j = 0; j + 1 < usedCount; ++j) {
        side.extend(bins, used[j]);
        n = _mm_add_epi32(n, countsOf(bins, used[j]));
        const __m128 cost = _mm_add_ps(_mm_mul_ps(side.areas(), _mm_cvtepi32_ps(n)),
                                       _mm_loadu_ps(rightCost[j + 1]));
        // Both sides non-empty (counts are below 2^31), the axis not flat, and cheaper.
        const __m128i twoSides =
            _mm_and_si128(_mm_cmpgt_epi32(n, _mm_setzero_si128()), _mm_cmplt_epi32(n, all));
        const __m128 better = _mm_and_ps(_mm_and_ps(_mm_castsi128_ps(twoSides), splittable),
                                         _mm_cmplt_ps(cost, bestCost));
        bestCost = select(better, bestCost, cost);
        bestPlane = _mm_castps_si128(select(better, _mm_castsi128_ps(bestPlane),
                                            _mm_castsi128_ps(_mm_set1_epi32(used[j] + 1))));
    }
    alignas(16) float costs[4];
    alignas(16) int32_t planes[4];
    _mm_store_ps(costs, bestCost);
    _mm_store_si128(reinterpret_cast<__m128i*>(planes), bestPlane);
    ObjectSplit best = frame;
    for (int a = 0; a < 3; ++a) {
        if (costs[a] < best.cost) {
            best.cost = costs[a];
            best.axis = a;
        }
    }
    if (best.axis < 0) {
        return best;
    }
    const int a = best.axis, k = planes[a];
    best.bin = k;
    SseBox left, right;
    for (int b = 0; b < k; ++b) {
        left.extend(bins.box[a][b].lower, bins.box[a][b].upper);
        best.leftCount += bins.count[a][b];
    }
    for (int b = binCount - 1; b >= k; --b) {
        right.extend(bins.box[a][b].lower, bins.box[a][b].upper);
    }
    SseBox overlap;
    overlap.lower = _mm_max_ps(left.lower, right.lower);
    overlap.upper = _mm_min_ps(left.upper, right.upper);
    best.overlapArea = overlap.toAabb().area();
    return best;
}

float binOverreach(const BinSet& bins, const ObjectSplit& frame, const Aabb& bounds) {
    // Lane a sums the extents along axis a of axis a's non-empty bins, bin by bin in increasing
    // order; an empty bin adds zero, which leaves the sum unchanged.
    __m128 sum = _mm_setzero_ps();
    for (uint32_t used = bins.usedMask(frame.bins); used != 0; used &= used - 1) {
        const int b = __builtin_ctz(used);
        __m128 extents = _mm_setzero_ps();
        for (int a = 0; a < 3; ++a) {
            const __m128 extent = _mm_sub_ps(bins.box[a][b].upper, xyzOf(bins.box[a][b].lower));
            extents = _mm_or_ps(extents, _mm_and_ps(axisLane(a), extent));
        }
        const __m128i empty = _mm_cmpeq_epi32(countsOf(bins, b), _mm_setzero_si128());
        sum = _mm_add_ps(sum, _mm_andnot_ps(_mm_castsi128_ps(empty), extents));
    }
    alignas(16) float sums[4];
    _mm_store_ps(sums, sum);
    float most = 0.0f;
    for (int a = 0; a < 3; ++a) {
        if (frame.scale[a] > 0.0f) {
            most = std::max(most, sums[a] / (bounds.upper[a] - bounds.lower[a]) - 1.0f);
        }
    }
    return most;
}

uint32_t leftCountOf(const BinSet& bins, const ObjectSplit& split) {
    uint32_t n = 0;
    for (int s = 0; s < split.bin; ++s) {
        n += bins.count[split.axis][s];
    }
    return n;
}

namespace {

// partitionRecords on one axis (a template argument, so that the loop reads the centroid's
// coordinate without a switch), the split's numbers and both sides' bounds in locals: with the
// bounds behind references every record's update went through memory and waited on the last
// one, and the split was read again after every store (it might have been overwritten).
//
// Two loops give the same result. Where neighbouring records mostly go the same way (meshes
// stored surface patch by patch, as scans and modelling tools write them), a branch on the side
// predicts well and is the faster. Where they do not (a mesh in random order), the branch
// misses about every other record; there the side is a select: each record is stored at the
// side's next place and added to both sides' bounds through a clamp to an infinity on the side
// it is not on (max(value, -inf) keeps a value for a minimum, max(value, +inf) is neutral; the
// upper bounds alike), so the bounds are those of the records each side gets, bit for bit. The
// first kProbe records go by the branch, and how often the side changes among them chooses the
// loop for the rest.
template <int axis>
void partitionOnAxis(const PrimRecord* first, const PrimRecord* last, const ObjectSplit& split,
                     PrimRecord* left, PrimRecord* right, RecordBounds& leftBounds,
                     RecordBounds& rightBounds) {
    constexpr std::ptrdiff_t kProbe = 16;
    constexpr int kMostChanges = kProbe / 4; // more changes than this: the select loop
    const float lower = split.lower[axis], scale = split.scale[axis];
    const int bin = split.bin;
    RecordBounds l = leftBounds, r = rightBounds;
    const PrimRecord* p = first;
    const PrimRecord* probeEnd = last - first > kProbe ? first + kProbe : last;
    // One record by the branch; returns its side.
    const auto byBranch = [&](const PrimRecord* q) {
        const __m128 lo = _mm_loadu_ps(&q->lower.x), hi = _mm_loadu_ps(&q->upper.x);
        const bool isLeft = binIsBelow(q->lower[axis] + q->upper[axis], lower, scale, bin);
        if (isLeft) {
            _mm_storeu_ps(&left->lower.x, lo);
            _mm_storeu_ps(&left->upper.x, hi);
            ++left;
            l.add(lo, hi);
        } else {
            _mm_storeu_ps(&right->lower.x, lo);
            _mm_storeu_ps(&right->upper.x, hi);
            ++right;
            r.add(lo, hi);
        }
        return isLeft;
    };
    int changes = 0;
    bool wasLeft = true;
    for (; p != probeEnd; ++p) {
        const bool isLeft = byBranch(p);
        changes += p != first && isLeft != wasLeft ? 1 : 0;
        wasLeft = isLeft;
    }
    if (changes <= kMostChanges) {
        for (; p != last; ++p) {
            byBranch(p);
        }
    } else {
        const __m128 lower4 = _mm_set1_ps(lower), scale4 = _mm_set1_ps(scale);
        const __m128 leftBelow4 = _mm_set1_ps(static_cast<float>(bin)); // binIsBelow's
        const __m128 infinity = _mm_set1_ps(kInfinity), sign = _mm_set1_ps(-0.0f);
        for (; p != last; ++p) {
            const __m128 lo = _mm_loadu_ps(&p->lower.x), hi = _mm_loadu_ps(&p->upper.x);
            const __m128 c = centroidOf(lo, hi);
            const __m128 below =
                _mm_cmplt_ps(_mm_mul_ps(_mm_sub_ps(c, lower4), scale4), leftBelow4);
            const __m128 isLeft =
                _mm_castsi128_ps(_mm_shuffle_epi32(_mm_castps_si128(below), axis * 0x55));
            const auto toLeft = static_cast<uintptr_t>(
                -static_cast<intptr_t>((_mm_movemask_ps(below) >> axis) & 1));
            const auto lp = reinterpret_cast<uintptr_t>(left);
            const auto rp = reinterpret_cast<uintptr_t>(right);
            auto* to = reinterpret_cast<PrimRecord*>(rp ^ ((lp ^ rp) & toLeft));
            _mm_storeu_ps(&to->lower.x, lo);
            _mm_storeu_ps(&to->upper.x, hi);
            left += toLeft & 1;
            right += 1 - (toLeft & 1);
            const __m128 minusIfLeft = _mm_or_ps(_mm_and_ps(isLeft, sign), infinity); // -inf/+inf
            const __m128 plusIfLeft = _mm_xor_ps(minusIfLeft, sign);                  // +inf/-inf
            l.box.lower = _mm_min_ps(l.box.lower, _mm_max_ps(lo, minusIfLeft));
            l.box.upper = _mm_max_ps(l.box.upper, _mm_min_ps(hi, plusIfLeft));
            l.centres.lower = _mm_min_ps(l.centres.lower, _mm_max_ps(c, minusIfLeft));
            l.centres.upper = _mm_max_ps(l.centres.upper, _mm_min_ps(c, plusIfLeft));
            r.box.lower = _mm_min_ps(r.box.lower, _mm_max_ps(lo, plusIfLeft));
            r.box.upper = _mm_max_ps(r.box.upper, _mm_min_ps(hi, minusIfLeft));
            r.centres.lower = _mm_min_ps(r.centres.lower, _mm_max_ps(c, plusIfLeft));
            r.centres.upper = _mm_max_ps(r.centres.upper, _mm_min_ps(c, minusIfLeft));
        }
    }
    leftBounds = l;
    rightBounds = r;
}

} // namespace

void partitionRecords(const PrimRecord* first, const PrimRecord* last, const ObjectSplit& split,
                      PrimRecord* left, PrimRecord* right, RecordBounds& leftBounds,
                      RecordBounds& rightBounds) {
    switch (split.axis) {
    case 0: partitionOnAxis<0>(first, last, split, left, right, leftBounds, rightBounds); break;
    case 1: partitionOnAxis<1>(first, last, split, left, right, leftBounds, rightBounds); break;
    default: partitionOnAxis<2>(first, last, split, left, right, leftBounds, rightBounds); break;
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
