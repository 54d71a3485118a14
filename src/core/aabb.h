#pragma once
// Axis-aligned bounding box.

#include "ray.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace raylab {

struct Aabb {
    glm::vec3 lower{kInfinity};
    glm::vec3 upper{-kInfinity};

    bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
    void extend(const glm::vec3& p) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    void extend(const Aabb& b) {
        lower = glm::min(lower, b.lower);
        upper = glm::max(upper, b.upper);
    }
    glm::vec3 center() const { return 0.5f * (lower + upper); }
    glm::vec3 extent() const { return empty() ? glm::vec3(0.0f) : upper - lower; }
    // Surface area; 0 for an empty box. Used by the SAH.
    float area() const {
        const glm::vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    // Length of the diagonal: the scene's "size" for scaling steps and epsilons.
    float diagonal() const;
};

} // namespace raylab
