// The frustums that need no AVX2 of their own: a block's camera pyramid from the camera's basis
// (frustumOfImageRect), and the tolerance every pyramid is pushed out by (bvh_frustum.h).

#include "bvh/bvh_frustum.h"
#include "bvh/bvh_packet.h"
#include "finite.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

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

bool frustumOfImageRect(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect,
                        RayFrustum& frustum) {
    static const bool simd = bvhSimdSupported();
    if (!simd || bvh.wideNodes.empty() || !isFinite(camera.origin) || !(rect.x0 <= rect.x1) ||
        !(rect.y0 <= rect.y1)) {
        return false;
    }
    // A ray's vector w = right (px - halfWidth) + up (halfHeight - py) + forward focal, with the
    // basis orthonormal, has dot(w, focal right - (x0 - halfWidth) forward) = focal (px - x0),
    // which is >= 0 exactly when px >= x0; likewise for the other three edges.
    const glm::vec3& right = camera.right;
    const glm::vec3& up = camera.up;
    const glm::vec3& forward = camera.forward;
    const float focal = camera.focal;
    const glm::vec3 inward[4] = {
        focal * right - (rect.x0 - camera.halfWidth) * forward, // px >= x0
        (rect.x1 - camera.halfWidth) * forward - focal * right, // px <= x1
        (camera.halfHeight - rect.y0) * forward - focal * up,   // py >= y0
        focal * up - (camera.halfHeight - rect.y1) * forward,   // py <= y1
    };
    frustum.apex = camera.origin;
    frustum.planeCount = 4;
    for (int j = 0; j < 4; ++j) {
        const float length = glm::length(inward[j]);
        if (!(length > 0.0f) || !std::isfinite(length) || !isFinite(inward[j])) {
            return false;
        }
        frustum.normal[j] = inward[j] / length;
        frustum.offset[j] = 0.0f;
    }
    frustum.tolerance = frustumTolerance(bvh, camera.origin);
    return true;
}

} // namespace raylab
