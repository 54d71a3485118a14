#include "lights/emitters.h"

#include "sampling/warp.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

namespace {

bool emits(const glm::vec3& emission) {
    return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f;
}

float triangleArea(const Triangle& t) {
    return 0.5f * glm::length(glm::cross(t.v1 - t.v0, t.v2 - t.v0));
}

} // namespace

bool hasEmittingMaterial(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const Material& m) { return emits(m.emission); });
}

EmitterTable buildEmitterTable(const Scene& scene) {
    EmitterTable table;
    if (!hasEmittingMaterial(scene)) {
        return table;
    }
    std::vector<double> power;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        if (t.material >= scene.materials.size() || !isValidTriangle(t)) {
            continue;
        }
        const glm::vec3& le = scene.materials[t.material].emission;
        const float area = triangleArea(t);
        const double p = kPi * (le.x + le.y + le.z) / 3.0 * area;
        if (!emits(le) || !(p > 0.0) || !std::isfinite(p)) {
            continue;
        }
        table.triangles.push_back(i);
        table.areas.push_back(area);
        power.push_back(p);
    }
    if (table.triangles.empty()) {
        return table;
    }
    double total = 0.0;
    for (double p : power) {
        total += p;
    }
    table.pickProbability.assign(scene.triangles.size(), 0.0f);
    double running = 0.0;
    for (std::size_t k = 0; k < power.size(); ++k) {
        running += power[k];
        table.cdf.push_back(static_cast<float>(running / total));
        table.pickProbability[table.triangles[k]] = static_cast<float>(power[k] / total);
    }
    table.cdf.back() = 1.0f;
    return table;
}

EmitterSample sampleEmitter(const Scene& scene, const EmitterTable& table, float emissionScale,
                            const glm::vec3& point, float pick, glm::vec2 v) {
    EmitterSample sample;
    if (table.empty()) {
        return sample;
    }
    const std::size_t k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(table.cdf.begin(), table.cdf.end(), pick) -
                                 table.cdf.begin()),
        table.cdf.size() - 1);
    const uint32_t index = table.triangles[k];
    const Triangle& t = scene.triangles[index];
    const glm::vec2 b = uniformTriangle(v);
    const glm::vec3 target = (1.0f - b.x - b.y) * t.v0 + b.x * t.v1 + b.y * t.v2;
    const glm::vec3 offset = target - point;
    const float distanceSquared = glm::dot(offset, offset);
    if (!(distanceSquared > 0.0f)) {
        return sample;
    }
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 direction = offset / distance;
    const glm::vec3 normal = geometricNormal(t);
    const float cosLight = -glm::dot(normal, direction); // > 0: the front face sees point
    if (!(cosLight > 0.0f)) {
        return sample;
    }
    sample.direction = direction;
    sample.distance = distance;
    sample.pdf = table.pickProbability[index] * distanceSquared / (table.areas[k] * cosLight);
    sample.radiance = scene.materials[t.material].emission * emissionScale;
    return sample;
}

float emitterPdf(const Scene& scene, const EmitterTable& table, uint32_t triangle,
                 const glm::vec3& direction, float distance) {
    if (table.empty() || triangle >= table.pickProbability.size()) {
        return 0.0f;
    }
    const float pick = table.pickProbability[triangle];
    if (!(pick > 0.0f)) {
        return 0.0f;
    }
    const Triangle& t = scene.triangles[triangle];
    const float cosLight = -glm::dot(geometricNormal(t), direction);
    if (!(cosLight > 0.0f)) {
        return 0.0f;
    }
    return pick * distance * distance / (triangleArea(t) * cosLight);
}

glm::vec3 emittedRadiance(const Scene& scene, uint32_t triangle, const glm::vec3& direction,
                          float emissionScale) {
    const Triangle& t = scene.triangles[triangle];
    if (t.material >= scene.materials.size()) {
        return glm::vec3(0.0f);
    }
    const glm::vec3& le = scene.materials[t.material].emission;
    if (!emits(le) || !(glm::dot(geometricNormal(t), direction) < 0.0f)) {
        return glm::vec3(0.0f);
    }
    return le * emissionScale;
}

} // namespace raylab
