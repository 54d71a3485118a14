#include "lights/sphere_light.h"

#include "sampling/warp.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

LightSample sampleSphereLight(const RenderSettings& settings, const glm::vec3& point,
                              const glm::vec3& facingNormal, glm::vec2 u) {
    const float radius = settings.light.radius;
    if (radius == 0.0f) {
        return lightAt(settings, point, facingNormal);
    }
    LightSample sample;
    const glm::vec3 r = settings.light.position - point;
    const float distanceSquared = glm::dot(r, r);
    const float radiusSquared = radius * radius;
    if (!(distanceSquared > radiusSquared)) {
        return sample;
    }
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 toCentre = r / distance;
    // 1 - cos(theta_max), with sin^2(theta_max) = r^2 / d^2, written without cancellation.
    const float sinSquaredMax = radiusSquared / distanceSquared;
    const float oneMinusCosMax = sinSquaredMax / (1.0f + std::sqrt(1.0f - sinSquaredMax));
    const glm::vec3 direction = frameAround(toCentre).toWorld(uniformCone(u, oneMinusCosMax));
    const float cosine = glm::dot(direction, facingNormal);
    if (!(cosine > 0.0f)) {
        return sample;
    }
    // Le * cos / pdf with Le = P / (4 pi^2 r^2) and pdf = 1 / (2 pi (1 - cos theta_max)).
    sample.direct =
        settings.light.power() * (cosine * oneMinusCosMax / (2.0f * kPi * radiusSquared));
    if (settings.shadows) {
        // The nearer intersection of the ray with the sphere: t = b - sqrt(b^2 - (d^2 - r^2)).
        const float b = glm::dot(direction, r);
        const float discriminant = b * b - (distanceSquared - radiusSquared);
        const float toSurface = b - std::sqrt(std::max(0.0f, discriminant));
        sample.needsShadowRay = true;
        sample.shadowRay =
            Ray{point, direction, settings.shadowEpsilon, toSurface - settings.shadowEpsilon};
    }
    return sample;
}

} // namespace raylab
