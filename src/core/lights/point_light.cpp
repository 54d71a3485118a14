#include "lights/point_light.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

namespace {
constexpr float kFourPi = 12.566370614359172f;
}

LightSample lightAt(const RenderSettings& settings, const glm::vec3& point,
                    const glm::vec3& facingNormal) {
    LightSample sample;
    const glm::vec3 r = settings.light.position - point;
    const float distanceSquared = glm::dot(r, r);
    if (!(distanceSquared > 0.0f)) {
        return sample;
    }
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 toLight = r / distance;
    const float cosine = glm::dot(toLight, facingNormal);
    if (!(cosine > 0.0f)) {
        return sample;
    }
    sample.direct = settings.light.power() * (cosine / (kFourPi * distanceSquared));
    if (settings.shadows) {
        sample.needsShadowRay = true;
        sample.shadowRay =
            Ray{point, toLight, settings.shadowEpsilon, distance - settings.shadowEpsilon};
    }
    return sample;
}

} // namespace raylab
