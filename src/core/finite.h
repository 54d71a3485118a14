#pragma once
// A vector whose every component is a finite float (no NaN, no infinity).

#include <cmath>
#include <glm/vec3.hpp>

namespace raylab {

inline bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace raylab
