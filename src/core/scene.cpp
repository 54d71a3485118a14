#include "scene.h"

#include "finite.h"

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

bool isValidTriangle(const Triangle& triangle) {
    if (!isFinite(triangle.v0) || !isFinite(triangle.v1) || !isFinite(triangle.v2)) {
        return false;
    }
    const glm::vec3 n = glm::cross(triangle.v1 - triangle.v0, triangle.v2 - triangle.v0);
    const float area2 = glm::dot(n, n);
    return area2 > 0.0f && std::isfinite(area2);
}

} // namespace raylab
