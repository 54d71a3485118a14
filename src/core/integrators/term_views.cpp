#include "integrators/term_views.h"

#include "integrators/path_integrator.h"
#include "lights/sphere_light.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

// 1 when one sample of the light (pair `pair`) reaches the point, else 0.
float visibleSample(const Bvh& bvh, const RenderSettings& settings, const SurfacePoint& s,
                    const PixelSampler& sampler, uint32_t pair, RayCounts& counts) {
    const LightSample light =
        sampleSphereLight(settings, s.point, s.facingNormal, sampler.get2D(pair));
    if (light.direct == glm::vec3(0.0f)) {
        return 0.0f; // facing away, or a light of power 0
    }
    if (!light.needsShadowRay) {
        return 1.0f;
    }
    ++counts.shadow;
    return anyHit(bvh, light.shadowRay) ? 0.0f : 1.0f;
}

} // namespace

float costHeat(float ops) {
    const float t = std::log2(1.0f + std::max(0.0f, ops)) / std::log2(1.0f + kCostHeatMax);
    return std::min(t, 1.0f);
}

glm::vec3 heatColor(float t) {
    static constexpr glm::vec3 kStops[] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 1},
                                           {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
    const float x = std::clamp(t, 0.0f, 1.0f) * 5.0f;
    const int i = std::min(static_cast<int>(x), 4);
    const float f = x - static_cast<float>(i);
    return kStops[i] * (1.0f - f) + kStops[i + 1] * f;
}

glm::vec3 shadeView(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                    const RenderSettings& settings, const Ray& cameraRay,
                    const PixelSampler& sampler, RayCounts& counts) {
    ++counts.primary;
    if (settings.view == View::Cost) {
        // The camera ray's closest hit and the lab's shadow ray, counted.
        TraversalCost cost;
        const Hit hit = closestHitCounted(bvh, cameraRay, cost);
        if (hit.found()) {
            const SurfacePoint s = surfaceAt(scene, cameraRay, hit);
            const LightSample light = lightAt(settings, s.point, s.facingNormal);
            if (light.needsShadowRay) {
                ++counts.shadow;
                anyHitCounted(bvh, light.shadowRay, cost);
            }
        }
        return heatColor(costHeat(static_cast<float>(cost.nodes + cost.triangles)));
    }
    const Hit hit = closestHit(bvh, cameraRay);
    if (!hit.found()) {
        return glm::vec3(0.0f);
    }
    const SurfacePoint s = surfaceAt(scene, cameraRay, hit);
    const bool path = settings.integrator == Integrator::Path;
    switch (settings.view) {
    case View::Beauty:
    case View::Cost: break;
    case View::Albedo: return s.rho;
    case View::Normal: return s.facingNormal * 0.5f + glm::vec3(0.5f);
    case View::Depth: return glm::vec3(hit.t);
    case View::Visibility:
        return glm::vec3(
            visibleSample(bvh, settings, s, sampler, path ? kPathFirstPair + 2 : 1, counts));
    case View::Direct:
        if (path) {
            return pathDirectLight(scene, bvh, emitters, settings, s, sampler, kPathFirstPair,
                                   EmitterStrategy::Mis, counts);
        } else {
            const LightSample light =
                sampleSphereLight(settings, s.point, s.facingNormal, sampler.get2D(1));
            if (light.needsShadowRay) {
                ++counts.shadow;
                if (anyHit(bvh, light.shadowRay)) {
                    return glm::vec3(0.0f);
                }
            }
            return light.direct;
        }
    case View::Indirect:
        if (path) {
            return tracePath(scene, bvh, emitters, settings, cameraRay, sampler, counts).indirect;
        }
        return settings.indirect3();
    }
    return glm::vec3(0.0f);
}

} // namespace raylab
