#include "navigation.h"

#include "core/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace raylab::viewer {

namespace {

// A horizontal unit vector along v's xz part, or `fallback` when v is (nearly) vertical.
glm::vec3 horizontal(const glm::vec3& v, const glm::vec3& fallback) {
    const glm::vec3 flat(v.x, 0.0f, v.z);
    const float length = glm::length(flat);
    return length > 1e-6f ? flat / length : fallback;
}

} // namespace

void turnCamera(float yawDegrees, float pitchDegrees, RenderSettings& settings) {
    Camera& camera = settings.camera;
    float yaw = std::remainder(camera.yawDegrees + yawDegrees, 360.0f); // [-180, 180]
    if (yaw == -180.0f) {
        yaw = 180.0f;
    }
    camera.yawDegrees = yaw;
    camera.pitchDegrees =
        std::clamp(camera.pitchDegrees + pitchDegrees, -kMaxPitchDegrees, kMaxPitchDegrees);
}

void moveCamera(float distance, RenderSettings& settings) {
    settings.camera.position += distance * forwardOf(settings.camera);
}

void applyNavAction(NavAction action, float step, RenderSettings& settings, float steps) {
    const glm::mat3 axes = worldFromCamera(settings.camera);
    const glm::vec3 forward = horizontal(axes[2], glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::vec3 right = horizontal(axes[0], glm::vec3(-1.0f, 0.0f, 0.0f));
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    glm::vec3& light = settings.light.position;
    const float distance = steps * step;
    const float degrees = steps * kTurnStepDegrees;
    switch (action) {
    case NavAction::CameraForward: moveCamera(distance, settings); break;
    case NavAction::CameraBack: moveCamera(-distance, settings); break;
    case NavAction::TurnLeft: turnCamera(degrees, 0.0f, settings); break;
    case NavAction::TurnRight: turnCamera(-degrees, 0.0f, settings); break;
    case NavAction::LightForward: light += distance * forward; break;
    case NavAction::LightBack: light -= distance * forward; break;
    case NavAction::LightLeft: light -= distance * right; break;
    case NavAction::LightRight: light += distance * right; break;
    case NavAction::LightDown: light -= distance * up; break;
    case NavAction::LightUp: light += distance * up; break;
    }
}

} // namespace raylab::viewer
