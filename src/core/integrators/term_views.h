#pragma once
// The light model's terms one at a time (RenderSettings::view): rho, D, N, the light's
// visibility, the normal and the depth of the surface a camera ray hits, as the integrator of the
// settings computes them, so that for the lab integrator beauty = albedo * (direct + indirect)
// sample by sample. 0 where the ray hits nothing.

#include "bvh/bvh.h"
#include "integrators/lab_shading.h"
#include "lights/emitters.h"
#include "render_settings.h"
#include "sampling/sampler.h"
#include "scene.h"

#include <glm/vec3.hpp>

namespace raylab {

// The cost view's scale: ops (BVH nodes visited plus triangles tested) to [0, 1] on a log scale,
// log2(1 + ops) / log2(1 + kCostHeatMax), 1 from kCostHeatMax operations on.
inline constexpr float kCostHeatMax = 1024.0f;
float costHeat(float ops);
// A colour ramp over [0, 1]: black, blue (0.2), cyan (0.4), green (0.6), yellow (0.8), red (1).
glm::vec3 heatColor(float t);

// One sample of settings.view (not View::Beauty) along cameraRay. The lab integrator's D is its
// light's (one sample of the sphere from the sampler's pair 1, as shadeLabSampled); the path
// integrator's adds the emitting triangles, and its N is one path's estimate.
glm::vec3 shadeView(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                    const RenderSettings& settings, const Ray& cameraRay,
                    const PixelSampler& sampler, RayCounts& counts);

} // namespace raylab
