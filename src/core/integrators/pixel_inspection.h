#pragma once
// Looking inside one pixel: the lab's equation for the pixel's centre ray with every number
// filled in, as the viewer's inspector and `raylab-render --inspect X,Y` show them:
//   R = E + rho * (D + N),   D = P * max(rhat . nhat, 0) / (4 pi |r|^2) unless shadowed,
// the shadow ray blocked by a triangle with eps < t < |r| - eps. With a light radius, D and the
// visibility are the means over 256 samples of the sphere (the shadow ray described is the one to
// its centre). With the path integrator, N is the first sample's estimate and `path` lists that
// sample's surfaces.

#include "bvh/bvh.h"
#include "integrators/path_integrator.h"
#include "lights/emitters.h"
#include "render_settings.h"
#include "scene.h"

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace raylab {

struct ShadowBlocker {
    uint32_t triangle = kNoTriangle; // the closest blocker on the shadow segment
    float t = 0.0f;                  // its distance along the unit shadow ray
};

struct PixelInspection {
    int x = 0;
    int y = 0;
    bool hit = false;
    // The rest holds for a hit only.
    uint32_t triangle = kNoTriangle; // index into Scene::triangles (the lab's order for its box)
    uint32_t material = 0;
    float t = 0.0f;                   // along the camera ray
    glm::vec3 point{0.0f};            // the hit point
    glm::vec3 rho{0.0f};              // the triangle's diffuse colour
    glm::vec3 normal{0.0f};           // nhat, turned to face the camera ray
    glm::vec3 toLight{0.0f};          // r, from the point to the light's centre
    float distance = 0.0f;            // |r|
    float cosTheta = 0.0f;            // rhat . nhat (negative: the light is behind the surface)
    glm::vec3 directUnshadowed{0.0f}; // P * max(rhat . nhat, 0) / (4 pi |r|^2)
    glm::vec3 direct{0.0f};           // D as R uses it: 0 in shadow
    bool shadowTested = false;        // shadows on and the light in front of the surface
    bool shadowed = false;
    std::optional<ShadowBlocker> blocker;
    float shadowEpsilon = 0.0f; // eps
    float shadowTMax = 0.0f;    // |r| - eps
    float visibility = 1.0f;    // the fraction of the light the point sees (0 or 1 for a point)
    glm::vec3 indirect{0.0f};   // N: the lab's constant, or the path integrator's estimate
    glm::vec3 emitted{0.0f};    // E = pi * Le of an emitting front face
    glm::vec3 radiance{0.0f};   // R
    std::array<uint8_t, 3> display{0, 0, 0}; // R after the display transform
    TraversalCost cameraCost;                // the camera ray's closest hit
    TraversalCost shadowCost;                // the shadow ray to the light's centre
    std::vector<PathVertexRecord> path;      // the path integrator's first sample
};

// The inspection of pixel (x, y) (0 <= x < width, 0 <= y < height). For the lab integrator, R is
// the pixel's first sample exactly as render() computes it.
PixelInspection inspectPixel(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                             const RenderSettings& settings, int x, int y);

} // namespace raylab
