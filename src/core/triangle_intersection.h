#pragma once
// Watertight ray-triangle intersection (Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013). A ray through a shared edge or vertex of a closed mesh hits at least
// one of the triangles that share it: no ray slips through, and no line shows between the two
// triangles of a quad.

#include "ray.h"

#include <cstdint>
#include <glm/vec3.hpp>

namespace raylab {

// Per-ray constants of the watertight test: the ray is sheared and permuted so that it runs
// along +z from the origin. Compute once per ray, then test any number of triangles.
struct WatertightRay {
    glm::vec3 origin{0.0f};
    int kx = 0, ky = 1, kz = 2; // permutation: kz is the axis of the largest |direction|
    float shearX = 0.0f, shearY = 0.0f, shearZ = 1.0f;
    float tMin = 0.0f;
    float tMax = kInfinity;
    bool valid = false; // false for a non-finite origin or direction, or a zero direction

    explicit WatertightRay(const Ray& ray);
};

// Tests one triangle. Returns true and sets t, u, v when the ray hits it with tMin < t < tMax.
// A triangle whose projected area is zero never hits; callers skip triangles that fail
// isValidTriangle (scene.h) before testing them, so degenerate ones never hit at all.
bool intersectTriangle(const WatertightRay& ray, const glm::vec3& v0, const glm::vec3& v1,
                       const glm::vec3& v2, float& t, float& u, float& v);

} // namespace raylab
