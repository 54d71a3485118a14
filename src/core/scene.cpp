#include "scene.h"

#include "finite.h"
#include "triangle_validity_sse.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

float Aabb::diagonal() const { return empty() ? 0.0f : glm::length(upper - lower); }

Aabb Scene::bounds() const {
    Aabb box;
    for (const Triangle& tri : triangles) {
        for (const glm::vec3* p : {&tri.v0, &tri.v1, &tri.v2}) {
            if (isFinite(*p)) {
                box.extend(*p);
            }
        }
    }
    return box;
}

glm::vec3 geometricNormal(const Triangle& triangle) {
    const glm::vec3 n = glm::cross(triangle.v1 - triangle.v0, triangle.v2 - triangle.v0);
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f);
}

bool isValidTriangle(const Triangle& triangle) { return isValidTriangle(TriangleLanes(triangle)); }

} // namespace raylab
