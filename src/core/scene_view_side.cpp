#include "scene_view_side.h"

#include "finite.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

namespace {

// The nearest and farthest depth (coordinate `depthAxis`) of the triangles covering each cell of
// a grid over axes (across, kUp) of the box: cell (i, j) has its centre at
// lower + (i + 0.5, j + 0.5) * extent / kViewDepthGrid. Cells nothing covers keep +inf and -inf.
struct DepthGrid {
    std::vector<float> nearest, farthest;
};

constexpr int kUp = 1; // the grid's rows run along world y

DepthGrid drawDepths(const Scene& scene, const Aabb& bounds, int across, int depthAxis) {
    constexpr int n = kViewDepthGrid;
    DepthGrid grid{std::vector<float>(n * n, kInfinity), std::vector<float>(n * n, -kInfinity)};
    const float lowerA = bounds.lower[across], lowerB = bounds.lower[kUp];
    const float cellA = (bounds.upper[across] - lowerA) / n;
    const float cellB = (bounds.upper[kUp] - lowerB) / n;
    if (!(cellA > 0.0f) || !(cellB > 0.0f)) {
        return grid; // the scene is flat across the view: nothing covers any cell
    }
    const float perCellA = 1.0f / cellA, perCellB = 1.0f / cellB;
    for (const Triangle& t : scene.triangles) {
        const glm::vec3 v[3] = {t.v0, t.v1, t.v2};
        if (!isFinite(v[0]) || !isFinite(v[1]) || !isFinite(v[2])) {
            continue;
        }
        // In cell units: the grid's centres are at integer + 0.5.
        float a[3], b[3], c[3];
        for (int k = 0; k < 3; ++k) {
            a[k] = (v[k][across] - lowerA) * perCellA;
            b[k] = (v[k][kUp] - lowerB) * perCellB;
            c[k] = v[k][depthAxis];
        }
        const float area = (a[1] - a[0]) * (b[2] - b[0]) - (a[2] - a[0]) * (b[1] - b[0]);
        if (!(std::fabs(area) > 0.0f)) {
            continue; // edge-on: it covers no cell
        }
        const float perArea = 1.0f / area;
        const int i0 =
            std::max(0, static_cast<int>(std::ceil(std::min({a[0], a[1], a[2]}) - 0.5f)));
        const int i1 =
            std::min(n - 1, static_cast<int>(std::floor(std::max({a[0], a[1], a[2]}) - 0.5f)));
        const int j0 =
            std::max(0, static_cast<int>(std::ceil(std::min({b[0], b[1], b[2]}) - 0.5f)));
        const int j1 =
            std::min(n - 1, static_cast<int>(std::floor(std::max({b[0], b[1], b[2]}) - 0.5f)));
        for (int j = j0; j <= j1; ++j) {
            const float pb = static_cast<float>(j) + 0.5f;
            for (int i = i0; i <= i1; ++i) {
                const float pa = static_cast<float>(i) + 0.5f;
                // Barycentric weights of the cell's centre (edge functions over the area).
                const float w0 = ((a[1] - pa) * (b[2] - pb) - (a[2] - pa) * (b[1] - pb)) * perArea;
                const float w1 = ((a[2] - pa) * (b[0] - pb) - (a[0] - pa) * (b[2] - pb)) * perArea;
                const float w2 = 1.0f - w0 - w1;
                if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) {
                    continue;
                }
                const float depth = w0 * c[0] + w1 * c[1] + w2 * c[2];
                const std::size_t cell =
                    static_cast<std::size_t>(j) * n + static_cast<std::size_t>(i);
                grid.nearest[cell] = std::min(grid.nearest[cell], depth);
                grid.farthest[cell] = std::max(grid.farthest[cell], depth);
            }
        }
    }
    return grid;
}

// The mean over the cells of depth behind the near face over the box's depth, for a view along
// +axis (the nearest surfaces) or -axis (the farthest).
float meanDepth(const std::vector<float>& depths, float nearFace, float boxDepth, float sign) {
    if (!(boxDepth > 0.0f)) {
        return 0.0f;
    }
    double sum = 0.0;
    for (float d : depths) {
        if (std::isfinite(d)) {
            sum += std::clamp(sign * (d - nearFace) / boxDepth, 0.0f, 1.0f);
        }
    }
    return static_cast<float>(sum / static_cast<double>(depths.size()));
}

} // namespace

float yawDegreesOf(ViewSide side) {
    switch (side) {
    case ViewSide::AlongPlusZ: return 0.0f;
    case ViewSide::AlongMinusZ: return 180.0f;
    case ViewSide::AlongPlusX: return 90.0f;
    case ViewSide::AlongMinusX: return -90.0f;
    }
    return 0.0f;
}

ViewDepths viewDepths(const Scene& scene) {
    ViewDepths depths;
    const Aabb bounds = scene.bounds();
    if (bounds.empty()) {
        return depths;
    }
    constexpr int x = 0, z = 2;
    const DepthGrid alongZ = drawDepths(scene, bounds, x, z);
    const DepthGrid alongX = drawDepths(scene, bounds, z, x);
    const glm::vec3 e = bounds.extent();
    depths.value[static_cast<int>(ViewSide::AlongPlusZ)] =
        meanDepth(alongZ.nearest, bounds.lower.z, e.z, 1.0f);
    depths.value[static_cast<int>(ViewSide::AlongMinusZ)] =
        meanDepth(alongZ.farthest, bounds.upper.z, e.z, -1.0f);
    depths.value[static_cast<int>(ViewSide::AlongPlusX)] =
        meanDepth(alongX.nearest, bounds.lower.x, e.x, 1.0f);
    depths.value[static_cast<int>(ViewSide::AlongMinusX)] =
        meanDepth(alongX.farthest, bounds.upper.x, e.x, -1.0f);
    return depths;
}

ViewSide framingSide(const Scene& scene) {
    const ViewDepths depths = viewDepths(scene);
    const float plusZ = depths.value[static_cast<int>(ViewSide::AlongPlusZ)];
    ViewSide best = ViewSide::AlongPlusZ;
    float bestDepth = plusZ;
    for (ViewSide side : {ViewSide::AlongMinusZ, ViewSide::AlongPlusX, ViewSide::AlongMinusX}) {
        const float depth = depths.value[static_cast<int>(side)];
        if (depth > 0.5f && depth > 2.0f * plusZ && depth > bestDepth) {
            best = side;
            bestDepth = depth;
        }
    }
    return best;
}

} // namespace raylab
