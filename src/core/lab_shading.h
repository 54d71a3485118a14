#pragma once
// The lab's light model, per colour channel:
//   D = P * max(rhat . nhat, 0) / (4 pi |r|^2),  R = rho * (D + N)
// r runs from the surface point to the light, nhat is the geometric normal turned to face the
// incoming ray, rho the triangle's diffuse colour, N the constant indirect term. The point is in
// shadow when a triangle lies on the segment towards the light with eps < t < |r| - eps.

#include "bvh.h"
#include "render_settings.h"
#include "scene.h"

#include <cstdint>
#include <glm/vec3.hpp>

namespace raylab {

struct RayCounts {
    std::uint64_t primary = 0;
    std::uint64_t shadow = 0;
};

// Direct light D arriving at point with facing normal nhat (0 when shadowed or facing away).
glm::vec3 directLight(const Bvh& bvh, const RenderSettings& settings, const glm::vec3& point,
                      const glm::vec3& facingNormal, RayCounts& counts);

// Radiance R along a camera ray; black when it hits nothing.
glm::vec3 shadeLab(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const Ray& ray, RayCounts& counts);

} // namespace raylab
