#include "scene_framing.h"

#include "camera.h"
#include "lights/emitters.h"
#include "scene_view_side.h"

#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>

namespace raylab {

namespace {

// The lab's box spans [-1, 1]^3: its diagonal is the unit the lab's constants were chosen for.
constexpr float kLabDiagonal = 3.4641016f;
constexpr float kLabShadowEpsilon = 1e-3f;
constexpr float kLabStep = 0.1f;
// Irradiance the framed light gives at the scene's centre, like the lab's light on its back wall.
constexpr float kFramedIrradiance = 0.4f;

float sceneScale(const Aabb& bounds) {
    const float diagonal = bounds.diagonal();
    return diagonal > 0.0f && std::isfinite(diagonal) ? diagonal / kLabDiagonal : 1.0f;
}

} // namespace

float scaledShadowEpsilon(const Aabb& bounds) { return kLabShadowEpsilon * sceneScale(bounds); }

float navigationStep(const Aabb& bounds) { return kLabStep * sceneScale(bounds); }

void frameScene(const Scene& scene, RenderSettings& settings) {
    const Aabb bounds = scene.bounds();
    if (bounds.empty()) {
        return;
    }
    const glm::vec3 center = bounds.center();
    const float radius = std::max(0.5f * bounds.diagonal(), 1e-6f);

    // Distance at which the bounding sphere fits the narrower of the two fields of view.
    const float halfVertical = 0.5f * glm::radians(settings.camera.verticalFovDegrees);
    const float aspect = static_cast<float>(settings.width) / static_cast<float>(settings.height);
    const float halfHorizontal = std::atan(std::tan(halfVertical) * aspect);
    const float distance = radius / std::sin(std::min(halfVertical, halfHorizontal));

    // Level, looking along +z or into an opening on another side (scene_view_side.h).
    settings.camera.yawDegrees = yawDegreesOf(framingSide(scene));
    settings.camera.pitchDegrees = 0.0f;
    const glm::vec3 forward = forwardOf(settings.camera);
    settings.camera.position = center - distance * forward;

    // Above and in front, outside the bounding sphere; power so that the centre receives the
    // lab's irradiance: E = P / (4 pi d^2) with d^2 = 2 radius^2. A scene with emitting
    // materials lights itself: its light starts at power 0.
    settings.light.position = center + glm::vec3(0.0f, radius, 0.0f) - radius * forward;
    settings.light.color = glm::vec3(1.0f);
    settings.light.intensity = hasEmittingMaterial(scene) ? 0.0f
                                                          : kFramedIrradiance * 4.0f * 3.14159265f *
                                                                2.0f * radius * radius;

    settings.shadowEpsilon = scaledShadowEpsilon(bounds);
}

} // namespace raylab

namespace raylab {

void placeForScene(const Scene& scene, bool isLabBox, const GivenSettings& given,
                   RenderSettings& settings) {
    RenderSettings placed = settings;
    if (isLabBox) {
        const RenderSettings lab;
        placed.camera = lab.camera;
        placed.light.position = lab.light.position;
        placed.light.color = lab.light.color;
        placed.light.intensity = lab.light.intensity;
        placed.shadowEpsilon = lab.shadowEpsilon;
    } else {
        frameScene(scene, placed);
    }
    if (given.cameraPosition) {
        placed.camera.position = settings.camera.position;
    }
    if (given.cameraYaw) {
        placed.camera.yawDegrees = settings.camera.yawDegrees;
    }
    if (given.cameraPitch) {
        placed.camera.pitchDegrees = settings.camera.pitchDegrees;
    }
    if (given.cameraFov) {
        placed.camera.verticalFovDegrees = settings.camera.verticalFovDegrees;
    }
    if (given.lightPosition) {
        placed.light.position = settings.light.position;
    }
    if (given.lightColor) {
        placed.light.color = settings.light.color;
    }
    if (given.lightIntensity) {
        placed.light.intensity = settings.light.intensity;
    }
    if (given.shadowEpsilon) {
        placed.shadowEpsilon = settings.shadowEpsilon;
    }
    settings = placed;
}

} // namespace raylab
