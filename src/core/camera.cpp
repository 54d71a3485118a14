#include "camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace raylab {

namespace {
constexpr float kMaxLookAtPitchDegrees = 89.9f;
}

glm::vec3 forwardOf(const Camera& camera) {
    const float yaw = glm::radians(camera.yawDegrees);
    const float pitch = glm::radians(camera.pitchDegrees);
    return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
}

glm::mat3 worldFromCamera(const Camera& camera) {
    const float yaw = glm::radians(camera.yawDegrees);
    const glm::vec3 forward = forwardOf(camera);
    // Right stays horizontal: cross(forward, world up) normalised, which for any pitch in
    // (-90, 90) is (-cos yaw, 0, sin yaw).
    const glm::vec3 right{-std::cos(yaw), 0.0f, std::sin(yaw)};
    const glm::vec3 up = glm::cross(right, forward);
    return glm::mat3(right, up, forward);
}

void lookAt(Camera& camera, const glm::vec3& target) {
    const glm::vec3 d = target - camera.position;
    const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
    if (horizontal == 0.0f && d.y == 0.0f) {
        return;
    }
    if (horizontal > 0.0f) {
        camera.yawDegrees = glm::degrees(std::atan2(d.x, d.z));
    }
    camera.pitchDegrees = std::clamp(glm::degrees(std::atan2(d.y, horizontal)),
                                     -kMaxLookAtPitchDegrees, kMaxLookAtPitchDegrees);
}

float focalLengthPixels(float verticalFovDegrees, int imageHeight) {
    return 0.5f * static_cast<float>(imageHeight) /
           std::tan(0.5f * glm::radians(verticalFovDegrees));
}

float verticalFovFromFocal(float focalPixels, int imageHeight) {
    return glm::degrees(2.0f * std::atan(0.5f * static_cast<float>(imageHeight) / focalPixels));
}

PrimaryRays::PrimaryRays(const Camera& camera, int width, int height)
    : origin(camera.position), halfWidth(0.5f * static_cast<float>(width)),
      halfHeight(0.5f * static_cast<float>(height)),
      focal(focalLengthPixels(camera.verticalFovDegrees, height)) {
    const glm::mat3 basis = worldFromCamera(camera);
    right = basis[0];
    up = basis[1];
    forward = basis[2];
}

Ray PrimaryRays::through(float px, float py) const {
    Ray ray;
    ray.origin = origin;
    ray.direction =
        glm::normalize(right * (px - halfWidth) + up * (halfHeight - py) + forward * focal);
    return ray;
}

} // namespace raylab
