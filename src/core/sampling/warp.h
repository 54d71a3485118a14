#pragma once
// Warps from the unit square to the directions and points light transport samples. Each takes
// u in [0, 1)^2 and states its density; none allocates or branches on data it does not need.

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace raylab {

inline constexpr float kPi = 3.14159265358979323846f;

// An orthonormal frame whose z axis is a given unit normal (Duff et al. 2017, branch-free).
struct Frame {
    glm::vec3 x, y, z;
    glm::vec3 toWorld(const glm::vec3& local) const {
        return local.x * x + local.y * y + local.z * z;
    }
};

inline Frame frameAround(const glm::vec3& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return Frame{glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
                 glm::vec3(b, sign + n.y * n.y * a, -n.y), n};
}

// The unit disk, area-preserving and with little distortion (Shirley and Chiu's concentric map).
inline glm::vec2 concentricDisk(glm::vec2 u) {
    const float a = 2.0f * u.x - 1.0f;
    const float b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) {
        return glm::vec2(0.0f);
    }
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (kPi / 2.0f) - (kPi / 4.0f) * (a / b);
    }
    return r * glm::vec2(std::cos(phi), std::sin(phi));
}

// A direction about +z with density cos(theta) / pi per steradian (z >= 0).
inline glm::vec3 cosineHemisphere(glm::vec2 u) {
    const glm::vec2 d = concentricDisk(u);
    const float z = std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return glm::vec3(d.x, d.y, z);
}

// A direction about +z, uniform over the cone cos(theta) >= cosThetaMax, given
// oneMinusCosThetaMax = 1 - cosThetaMax (passed separately so that narrow cones keep their
// precision). Density 1 / (2 pi oneMinusCosThetaMax) per steradian.
inline glm::vec3 uniformCone(glm::vec2 u, float oneMinusCosThetaMax) {
    const float oneMinusCos = u.x * oneMinusCosThetaMax;
    const float cosTheta = 1.0f - oneMinusCos;
    const float sinTheta = std::sqrt(std::max(0.0f, oneMinusCos * (2.0f - oneMinusCos)));
    const float phi = 2.0f * kPi * u.y;
    return glm::vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

// Barycentric weights (b1, b2) of a point uniform over a triangle's area: the point is
// (1 - b1 - b2) v0 + b1 v1 + b2 v2, density 1 / area.
inline glm::vec2 uniformTriangle(glm::vec2 u) {
    const float s = std::sqrt(u.x);
    return glm::vec2(1.0f - s, u.y * s);
}

} // namespace raylab
