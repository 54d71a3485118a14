#include "camera.h"

#include "bvh/bvh.h"
#include "watertight_avx2.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace raylab {

namespace {
constexpr float kMaxLookAtPitchDegrees = 89.9f;

// through() on 8 lanes: the same IEEE single-precision operations in the same order (core builds
// with -ffp-contract=off), i.e. v = (right * (px - halfWidth) + up * (halfHeight - py)) +
// forward * focal per component, then glm::normalize's v * (1 / sqrt((x*x + y*y) + z*z)).
RAYLAB_AVX2 void through8Avx2(const PrimaryRays& p, const float* px, const float* py, int count,
                              RayPacket& rays) {
    __m256 x, y;
    if (count == 8) { // loaded as the caller stored them (no store-forwarding stall)
        x = _mm256_loadu_ps(px);
        y = _mm256_loadu_ps(py);
    } else {
        alignas(32) float xs[8] = {};
        alignas(32) float ys[8] = {};
        for (int i = 0; i < count; ++i) {
            xs[i] = px[i];
            ys[i] = py[i];
        }
        x = _mm256_load_ps(xs);
        y = _mm256_load_ps(ys);
    }
    const __m256 a = _mm256_sub_ps(x, _mm256_set1_ps(p.halfWidth));
    const __m256 b = _mm256_sub_ps(_mm256_set1_ps(p.halfHeight), y);
    __m256 v[3];
    for (int k = 0; k < 3; ++k) {
        v[k] = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(p.right[k]), a),
                                           _mm256_mul_ps(_mm256_set1_ps(p.up[k]), b)),
                             _mm256_set1_ps(p.forward[k] * p.focal));
    }
    const __m256 dot =
        _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(v[0], v[0]), _mm256_mul_ps(v[1], v[1])),
                      _mm256_mul_ps(v[2], v[2]));
    const __m256 inverse = _mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_sqrt_ps(dot));
    for (int k = 0; k < 3; ++k) {
        _mm256_store_ps(rays.origin[k], _mm256_set1_ps(p.origin[k]));
        _mm256_store_ps(rays.direction[k], _mm256_mul_ps(v[k], inverse));
    }
    const Ray defaults;
    _mm256_store_ps(rays.tMin, _mm256_set1_ps(defaults.tMin));
    _mm256_store_ps(rays.tMax, _mm256_set1_ps(defaults.tMax));
    rays.lanes = firstLanes(count);
}
} // namespace

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

void orbitCamera(Camera& camera, const glm::vec3& pivot, float yawDegrees, float pitchDegrees) {
    constexpr float kMaxOrbitPitchDegrees = 85.0f;
    const glm::vec3 toPivot = pivot - camera.position;
    const float distance = glm::length(toPivot);
    if (!(distance > 0.0f) || !std::isfinite(distance)) {
        return;
    }
    const glm::vec3 d = toPivot / distance;
    const float yaw = glm::degrees(std::atan2(d.x, d.z)) + yawDegrees;
    const float pitch =
        std::clamp(glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f))) + pitchDegrees,
                   -kMaxOrbitPitchDegrees, kMaxOrbitPitchDegrees);
    const float cy = std::cos(glm::radians(yaw));
    const float sy = std::sin(glm::radians(yaw));
    const float cp = std::cos(glm::radians(pitch));
    const float sp = std::sin(glm::radians(pitch));
    const glm::vec3 forward(sy * cp, sp, cy * cp);
    camera.position = pivot - distance * forward;
    camera.yawDegrees = yaw;
    camera.pitchDegrees = pitch;
}

std::vector<Camera> turntableCameras(const Camera& start, const glm::vec3& centre, int frames) {
    std::vector<Camera> cameras{start}; // frame 0 is the camera itself, bit for bit
    for (int k = 1; k < frames; ++k) {
        const double degrees = 360.0 * k / frames;
        const double radians = glm::radians(degrees);
        const double c = std::cos(radians);
        const double s = std::sin(radians);
        // Turning by theta about y maps (x, z) to (x cos + z sin, z cos - x sin): what adding
        // theta to the yaw does to the forward axis (sin yaw, ., cos yaw).
        const glm::dvec3 offset = glm::dvec3(start.position) - glm::dvec3(centre);
        Camera camera = start;
        camera.position = centre + glm::vec3(glm::dvec3(offset.x * c + offset.z * s, offset.y,
                                                        offset.z * c - offset.x * s));
        camera.yawDegrees = static_cast<float>(std::remainder(start.yawDegrees + degrees, 360.0));
        cameras.push_back(camera);
    }
    return cameras;
}

void panCamera(Camera& camera, float right, float up) {
    const glm::mat3 axes = worldFromCamera(camera);
    camera.position += right * axes[0] + up * axes[1];
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

glm::vec3 PrimaryRays::cameraFrom(const glm::vec3& world) const {
    const glm::vec3 v = world - origin;
    return {glm::dot(v, right), glm::dot(v, up), glm::dot(v, forward)};
}

glm::vec2 PrimaryRays::imageFrom(const glm::vec3& cameraPoint) const {
    const float scale = focal / cameraPoint.z;
    return {halfWidth + cameraPoint.x * scale, halfHeight - cameraPoint.y * scale};
}

void PrimaryRays::through8(const float* px, const float* py, int count, RayPacket& rays) const {
    static const bool simd = bvhSimdSupported();
    if (simd) {
        through8Avx2(*this, px, py, count, rays);
        return;
    }
    rays.lanes = 0;
    for (int i = 0; i < count; ++i) {
        rays.set(i, through(px[i], py[i]));
    }
}

} // namespace raylab
