// The tolerance every frustum's pyramid is pushed out by (bvh_frustum.h), which needs no AVX2 of
// its own.

#include "bvh/bvh_frustum.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

float maxAbs(const glm::vec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

} // namespace

float frustumTolerance(const Bvh& bvh, const glm::vec3& apex) {
    constexpr float kToleranceScale = 4e-5f;
    // The node boxes reach boxPad beyond the largest coordinate. (Read from the Bvh: a block's
    // two frustums computing the root's box each cost the box's lab passes 2.5%.)
    return kToleranceScale * std::max(bvh.largestCoordinate + bvh.boxPad, maxAbs(apex));
}

} // namespace raylab
