#include "integrators/term_views.h"

#include "integrators/path_integrator.h"
#include "lights/sphere_light.h"

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

glm::vec3 shadeView(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                    const RenderSettings& settings, const Ray& cameraRay,
                    const PixelSampler& sampler, RayCounts& counts) {
    ++counts.primary;
    const Hit hit = closestHit(bvh, cameraRay);
    if (!hit.found()) {
        return glm::vec3(0.0f);
    }
    const SurfacePoint s = surfaceAt(scene, cameraRay, hit);
    const bool path = settings.integrator == Integrator::Path;
    switch (settings.view) {
    case View::Beauty: break;
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
