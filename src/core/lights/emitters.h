#pragma once
// A scene's emitting triangles as area lights (DESIGN.md section 5): each emits radiance
// Le = material.emission * emissionScale from its front face (the side its winding's normal
// points to) and has power pi * Le * area. Next-event estimation picks one triangle with
// probability proportional to its power (the mean of its channels) and a point uniformly on it.

#include "ray.h"
#include "scene.h"

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace raylab {

struct EmitterTable {
    std::vector<uint32_t> triangles; // scene triangle indices, valid and emitting
    std::vector<float> cdf;          // cdf[i]: the probability of picking triangles[0..i]
    std::vector<float> areas;        // world units^2, per entry of triangles
    // The probability that a pick chooses scene triangle i (0 for triangles that do not emit);
    // empty when the table is.
    std::vector<float> pickProbability;

    bool empty() const { return triangles.empty(); }
};

// True when some material of the scene emits (a quick test: materials, not triangles).
bool hasEmittingMaterial(const Scene& scene);

// The table of a scene's triangles as they are now (rebuild when triangles or emission change;
// the emission scale does not change it).
EmitterTable buildEmitterTable(const Scene& scene);

// One sample of the light that emitting triangles send to `point`.
struct EmitterSample {
    glm::vec3 radiance{0.0f};  // Le * emissionScale arriving along direction; 0: no light
    glm::vec3 direction{0.0f}; // unit, from point to the sampled point
    float distance = 0.0f;     // to the sampled point
    float pdf = 0.0f;          // of direction, per steradian (pick probability included)
};

// u.x picks the triangle (by power), v the point on it (uniform by area). radiance is 0 when the
// triangle's front face does not face point or the point lies on the triangle's plane.
EmitterSample sampleEmitter(const Scene& scene, const EmitterTable& table, float emissionScale,
                            const glm::vec3& point, float pick, glm::vec2 v);

// The density per steradian with which sampleEmitter would choose the direction from `from` that
// reaches `hitPoint` on scene triangle `triangle` at distance `distance` (0 if it never would).
float emitterPdf(const Scene& scene, const EmitterTable& table, uint32_t triangle,
                 const glm::vec3& direction, float distance);

// The emitted radiance Le * emissionScale that scene triangle `triangle` sends along a ray of
// direction `direction` that hits it: 0 from behind (or for a non-emitting material).
glm::vec3 emittedRadiance(const Scene& scene, uint32_t triangle, const glm::vec3& direction,
                          float emissionScale);

} // namespace raylab
