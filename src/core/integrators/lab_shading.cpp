#include "integrators/lab_shading.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

SurfacePoint surfaceAt(const Scene& scene, const Ray& ray, const Hit& hit) {
    const Triangle& triangle = scene.triangles[hit.triangle];
    SurfacePoint s;
    s.point = ray.origin + hit.t * ray.direction;
    s.facingNormal = geometricNormal(triangle);
    if (glm::dot(s.facingNormal, ray.direction) > 0.0f) {
        s.facingNormal = -s.facingNormal;
    }
    s.rho = scene.materials[triangle.material].diffuse;
    return s;
}

glm::vec3 labRadiance(const RenderSettings& settings, const glm::vec3& rho,
                      const glm::vec3& direct) {
    return rho * (direct + settings.indirect3());
}

glm::vec3 directLight(const Bvh& bvh, const RenderSettings& settings, const glm::vec3& point,
                      const glm::vec3& facingNormal, RayCounts& counts) {
    const LightSample sample = lightAt(settings, point, facingNormal);
    if (sample.needsShadowRay) {
        ++counts.shadow;
        if (anyHit(bvh, sample.shadowRay)) {
            return glm::vec3(0.0f);
        }
    }
    return sample.direct;
}

glm::vec3 shadeLab(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const Ray& ray, RayCounts& counts) {
    ++counts.primary;
    const Hit hit = closestHit(bvh, ray);
    if (!hit.found()) {
        return glm::vec3(0.0f);
    }
    const SurfacePoint s = surfaceAt(scene, ray, hit);
    return labRadiance(settings, s.rho,
                       directLight(bvh, settings, s.point, s.facingNormal, counts));
}

} // namespace raylab
