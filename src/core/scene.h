#pragma once
// The geometry and materials the tracer sees: a flat list of triangles, each with a material.

#include "aabb.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace raylab {

// A Lambertian material: diffuse reflectance rho per colour channel, each in [0, 1], and the
// radiance Le it emits from the front face of its triangles (the side the winding's normal points
// to), each channel finite and >= 0 (W/m^2/sr; MTL Ke, glTF emissive). Emitted R is pi * Le.
struct Material {
    std::string name;
    glm::vec3 diffuse{0.75f}; // rho; 0.75 grey where a file gives none
    glm::vec3 emission{0.0f}; // Le; 0 for a surface that does not emit
};

// One triangle. The geometric normal is normalize(cross(v1 - v0, v2 - v0)); shading turns it to
// face the incoming ray, so winding does not matter for light.
struct Triangle {
    glm::vec3 v0{0.0f};
    glm::vec3 v1{0.0f};
    glm::vec3 v2{0.0f};
    uint32_t material = 0; // index into Scene::materials
};

struct Scene {
    std::string name; // "cornell" or the file the scene came from
    std::vector<Triangle> triangles;
    std::vector<Material> materials;

    Aabb bounds() const; // of all finite vertices; empty() when there are none
};

// Geometric unit normal of a triangle; (0,0,0) for a degenerate one.
glm::vec3 geometricNormal(const Triangle& triangle);

// True when all three vertices are finite and the triangle has non-zero area.
bool isValidTriangle(const Triangle& triangle);

} // namespace raylab
