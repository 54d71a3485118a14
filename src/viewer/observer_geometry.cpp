#include "observer_geometry.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace raylab::viewer {

namespace {

constexpr float kMarkerPerSize = 0.02f; // markers' half-length per scene size

glm::vec3 centreOf(const Aabb& bounds) {
    return bounds.empty() ? glm::vec3(0.0f) : bounds.center();
}

void appendMarker(const glm::vec3& at, float half, OverlayRay kind,
                  std::vector<WorldSegment>& out) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 d(0.0f);
        d[axis] = half;
        out.push_back({at - d, at + d, kind});
    }
}

} // namespace

float observedSceneSize(const Aabb& bounds) {
    const float size = bounds.empty() ? 0.0f : bounds.diagonal();
    return std::isfinite(size) && size > 0.0f ? size : 1.0f;
}

Camera observerStart(const Camera& lab, const Aabb& bounds) {
    const glm::vec3 centre = centreOf(bounds);
    const float size = observedSceneSize(bounds);
    const glm::vec3 fromCentre = lab.position - centre;
    const float distance = glm::length(fromCentre);
    const glm::vec3 back = distance > 1e-6f * size ? fromCentre / distance : -forwardOf(lab);
    Camera observer;
    observer.position = lab.position + back * size + glm::vec3(0.0f, 0.4f * size, 0.0f);
    observer.verticalFovDegrees = kLabVerticalFovDegrees;
    lookAt(observer, centre);
    return observer;
}

float imagePlaneDistance(const Camera& lab, const Aabb& bounds) {
    const float depth = glm::dot(centreOf(bounds) - lab.position, forwardOf(lab));
    return std::max(0.5f * depth, 0.25f * observedSceneSize(bounds));
}

std::array<glm::vec3, 4> imagePlaneCorners(const PrimaryRays& lab, int width, int height,
                                           float depth) {
    const float w = static_cast<float>(width), h = static_cast<float>(height);
    const glm::vec2 pixels[4] = {{0.0f, 0.0f}, {w, 0.0f}, {w, h}, {0.0f, h}};
    std::array<glm::vec3, 4> corners;
    for (int i = 0; i < 4; ++i) {
        const Ray ray = lab.through(pixels[i].x, pixels[i].y);
        corners[static_cast<std::size_t>(i)] =
            ray.origin + ray.direction * (depth / glm::dot(ray.direction, lab.forward));
    }
    return corners;
}

std::vector<WorldSegment> labCameraSegments(const Camera& lab, int width, int height, float depth,
                                            float marker) {
    std::vector<WorldSegment> out;
    appendMarker(lab.position, marker, OverlayRay::LabCamera, out);
    const auto corners = imagePlaneCorners(PrimaryRays(lab, width, height), width, height, depth);
    for (std::size_t i = 0; i < 4; ++i) {
        out.push_back({lab.position, corners[i], OverlayRay::LabCamera});
    }
    for (std::size_t i = 0; i < 4; ++i) {
        out.push_back({corners[i], corners[(i + 1) % 4], OverlayRay::LabCamera});
    }
    return out;
}

std::vector<WorldSegment> lightSegments(const PointLight& light, const glm::vec3& viewer,
                                        float marker) {
    std::vector<WorldSegment> out;
    appendMarker(light.position, marker, OverlayRay::Light, out);
    if (!(light.radius > 0.0f)) {
        return out;
    }
    // Two unit axes of the plane facing the viewer (any plane when the viewer is at the centre).
    glm::vec3 towards = viewer - light.position;
    towards = glm::length(towards) > 0.0f ? glm::normalize(towards) : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 helper =
        std::abs(towards.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(helper, towards));
    const glm::vec3 v = glm::cross(towards, u);
    const auto around = [&](int k) {
        const float angle =
            2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / kLightCircleSegments;
        return light.position + light.radius * (std::cos(angle) * u + std::sin(angle) * v);
    };
    for (int k = 0; k < kLightCircleSegments; ++k) {
        out.push_back({around(k), around((k + 1) % kLightCircleSegments), OverlayRay::Light});
    }
    return out;
}

std::vector<ImageSegment> observerOverlay(const Camera& observer, int width, int height,
                                          const Camera& lab, int labWidth, int labHeight,
                                          const PointLight& light, const Aabb& bounds,
                                          float nearDepth) {
    const float marker = kMarkerPerSize * observedSceneSize(bounds);
    std::vector<WorldSegment> world =
        labCameraSegments(lab, labWidth, labHeight, imagePlaneDistance(lab, bounds), marker);
    const std::vector<WorldSegment> lit = lightSegments(light, observer.position, marker);
    world.insert(world.end(), lit.begin(), lit.end());
    return projectSegments(PrimaryRays(observer, width, height), width, height, nearDepth, world);
}

} // namespace raylab::viewer
