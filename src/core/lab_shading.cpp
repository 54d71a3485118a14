#include "lab_shading.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

namespace {
constexpr float kFourPi = 12.566370614359172f;
}

glm::vec3 directLight(const Bvh& bvh, const RenderSettings& settings, const glm::vec3& point,
                      const glm::vec3& facingNormal, RayCounts& counts) {
    const glm::vec3 r = settings.light.position - point;
    const float distanceSquared = glm::dot(r, r);
    if (!(distanceSquared > 0.0f)) {
        return glm::vec3(0.0f);
    }
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 toLight = r / distance;
    const float cosine = glm::dot(toLight, facingNormal);
    if (!(cosine > 0.0f)) {
        return glm::vec3(0.0f);
    }
    if (settings.shadows) {
        const Ray shadowRay{point, toLight, settings.shadowEpsilon,
                            distance - settings.shadowEpsilon};
        ++counts.shadow;
        if (anyHit(bvh, shadowRay)) {
            return glm::vec3(0.0f);
        }
    }
    return settings.light.power() * (cosine / (kFourPi * distanceSquared));
}

glm::vec3 shadeLab(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const Ray& ray, RayCounts& counts) {
    ++counts.primary;
    const Hit hit = closestHit(bvh, ray);
    if (!hit.found()) {
        return glm::vec3(0.0f);
    }
    const Triangle& triangle = scene.triangles[hit.triangle];
    const glm::vec3 point = ray.origin + hit.t * ray.direction;
    glm::vec3 normal = geometricNormal(triangle);
    if (glm::dot(normal, ray.direction) > 0.0f) {
        normal = -normal;
    }
    const glm::vec3 rho = scene.materials[triangle.material].diffuse;
    return rho * (directLight(bvh, settings, point, normal, counts) + settings.indirect3());
}

} // namespace raylab
