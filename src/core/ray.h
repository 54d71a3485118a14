#pragma once
// Rays and hit records shared by every intersection routine.

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>

namespace raylab {

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
inline constexpr uint32_t kNoTriangle = std::numeric_limits<uint32_t>::max();

// A ray segment: points origin + t * direction with tMin < t < tMax (both bounds exclusive).
// direction need not be unit length; t is then measured in units of |direction|.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    float tMin = 0.0f;
    float tMax = kInfinity;
};

// The closest intersection found so far. (u, v) are the barycentric weights of the triangle's
// second and third vertex: p = (1 - u - v) * v0 + u * v1 + v * v2.
struct Hit {
    float t = kInfinity;
    float u = 0.0f;
    float v = 0.0f;
    uint32_t triangle = kNoTriangle; // index into Scene::triangles
    bool found() const { return triangle != kNoTriangle; }
};

// Whether a hit at t on triangle `index` beats the closest so far (at bestT, on bestTriangle):
// the nearer wins, and at equal t the lower index, so that no traversal's answer depends on the
// order it tests triangles in.
inline bool closerHit(float t, uint32_t index, float bestT, uint32_t bestTriangle) {
    return t < bestT || (t == bestT && index < bestTriangle);
}

} // namespace raylab
