#include "bvh_spatial_split.h"

#include "bvh_clip.h"

#include <algorithm>
#include <array>

namespace raylab {

namespace {

Aabb boxOf(const PrimRecord& r) { return Aabb{r.lower, r.upper}; }

__m128 toSse(const glm::vec3& v) { return _mm_setr_ps(v.x, v.y, v.z, 0.0f); }

// The plane between bin i - 1 and bin i (0 < i < kSpatialBins) of [lower, lower + extent].
float planeOf(float lower, float extent, int i) {
    return lower + extent * (static_cast<float>(i) / static_cast<float>(kSpatialBins));
}

// The bin of coordinate x, for scale = kSpatialBins / extent.
int binOfCoordinate(float x, float lower, float scale) {
    const float b = (x - lower) * scale;
    return b <= 0.0f ? 0 : std::min(static_cast<int>(b), kSpatialBins - 1);
}

} // namespace

SpatialSplit findSpatialSplit(const Scene& scene, const std::vector<PrimRecord>& refs,
                              const Aabb& bounds, float slack) {
    SpatialSplit best;
    const glm::vec3 extent = bounds.extent();
    for (int a = 0; a < 3; ++a) {
        if (!(extent[a] > 0.0f)) {
            continue;
        }
        std::array<SseBox, kSpatialBins> box{};
        std::array<uint32_t, kSpatialBins> entering{}, leaving{};
        const float scale = static_cast<float>(kSpatialBins) / extent[a];
        for (const PrimRecord& r : refs) {
            const int first = binOfCoordinate(r.lower[a], bounds.lower[a], scale);
            const int last = binOfCoordinate(r.upper[a], bounds.lower[a], scale);
            ++entering[first];
            ++leaving[last];
            if (first == last) {
                box[first].extend(_mm_loadu_ps(&r.lower.x), _mm_loadu_ps(&r.upper.x));
                continue;
            }
            // Clip the triangle bin by bin: the part left of each plane goes to that bin.
            const Triangle& t = scene.triangles[r.sceneIndex];
            Aabb rest = boxOf(r);
            for (int i = first; i < last && !rest.empty(); ++i) {
                Aabb left, right;
                splitBox(t, rest, a, planeOf(bounds.lower[a], extent[a], i + 1), slack, left,
                         right);
                if (!left.empty()) {
                    box[i].extend(toSse(left.lower), toSse(left.upper));
                }
                rest = right;
            }
            if (!rest.empty()) {
                box[last].extend(toSse(rest.lower), toSse(rest.upper));
            }
        }
        // Sweep: right side from the top, then left side from the bottom.
        std::array<float, kSpatialBins> rightCost{};
        std::array<uint32_t, kSpatialBins> rightCount{};
        Aabb acc;
        uint32_t n = 0;
        for (int s = kSpatialBins - 1; s > 0; --s) {
            acc.extend(box[s].toAabb());
            n += leaving[s];
            rightCost[s] = acc.area() * static_cast<float>(n);
            rightCount[s] = n;
        }
        acc = Aabb{};
        n = 0;
        for (int s = 1; s < kSpatialBins; ++s) {
            acc.extend(box[s - 1].toAabb());
            n += entering[s - 1];
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

bool applySpatialSplit(const Scene& scene, const std::vector<PrimRecord>& refs,
                       const SpatialSplit& split, float slack, std::vector<PrimRecord>& left,
                       std::vector<PrimRecord>& right) {
    const int a = split.axis;
    left.clear();
    right.clear();
    for (const PrimRecord& r : refs) {
        if (r.upper[a] <= split.position) {
            left.push_back(r);
        } else if (r.lower[a] >= split.position) {
            right.push_back(r);
        } else {
            Aabb l, rr;
            splitBox(scene.triangles[r.sceneIndex], boxOf(r), a, split.position, slack, l, rr);
            if (!l.empty()) {
                left.push_back({l.lower, r.sceneIndex, l.upper});
            }
            if (!rr.empty()) {
                right.push_back({rr.lower, r.sceneIndex, rr.upper});
            }
            if (l.empty() && rr.empty()) { // only if rounding lost the part: keep it whole
                left.push_back(r);
            }
        }
    }
    return !left.empty() && !right.empty();
}

} // namespace raylab
