// The pinhole camera: axes, pixel-centre rays, field of view and look-at.

#include "core/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

namespace raylab {
namespace {

void expectVecNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Camera, LabDefaultLooksAlongPlusZWithRightAlongMinusX) {
    const Camera lab;
    EXPECT_EQ(lab.position, glm::vec3(0.0f, 0.0f, -3.0f));
    const glm::mat3 basis = worldFromCamera(lab);
    expectVecNear(basis[0], {-1.0f, 0.0f, 0.0f});
    expectVecNear(basis[1], {0.0f, 1.0f, 0.0f});
    expectVecNear(basis[2], {0.0f, 0.0f, 1.0f});
}

TEST(Camera, LabFieldOfViewMeansFocalLengthEqualsImageHeight) {
    EXPECT_NEAR(focalLengthPixels(kLabVerticalFovDegrees, 500), 500.0f, 1e-3f);
    EXPECT_NEAR(verticalFovFromFocal(500.0f, 500), kLabVerticalFovDegrees, 1e-4f);
    EXPECT_NEAR(focalLengthPixels(90.0f, 200), 100.0f, 1e-3f);
    for (float fov : {1.0f, 30.0f, 90.0f, 170.0f}) {
        EXPECT_NEAR(verticalFovFromFocal(focalLengthPixels(fov, 720), 720), fov, 1e-3f);
    }
}

TEST(Camera, PixelCentreRaysFollowTheLabFormula) {
    const Camera lab;
    const int w = 500, h = 500;
    const PrimaryRays rays(lab, w, h);
    // d = normalize(right (x + 0.5 - W/2) + up (H/2 - y - 0.5) + forward f), f = H.
    for (const auto& [x, y] : {std::pair{0, 0}, {499, 0}, {0, 499}, {250, 250}, {123, 321}}) {
        const Ray ray = rays.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        const glm::vec3 expected =
            glm::normalize(glm::vec3(-(static_cast<float>(x) + 0.5f - 250.0f),
                                     250.0f - static_cast<float>(y) - 0.5f, 500.0f));
        expectVecNear(ray.direction, expected);
        EXPECT_EQ(ray.origin, lab.position);
    }
    // The top-left pixel looks up and to the image's left, which is +x in world space.
    const Ray topLeft = rays.through(0.5f, 0.5f);
    EXPECT_GT(topLeft.direction.x, 0.0f);
    EXPECT_GT(topLeft.direction.y, 0.0f);
}

TEST(Camera, ImageFromInvertsThroughForAnyCamera) {
    Camera camera;
    camera.position = {0.3f, -0.2f, -2.5f};
    camera.yawDegrees = 17.0f;
    camera.pitchDegrees = -11.0f;
    camera.verticalFovDegrees = 70.0f;
    const PrimaryRays rays(camera, 320, 200);
    for (const auto& [px, py] :
         {std::pair{0.5f, 0.5f}, {319.5f, 10.0f}, {160.0f, 100.0f}, {-40.0f, 250.0f}}) {
        const Ray ray = rays.through(px, py);
        const float depth = 3.7f;
        const glm::vec3 world = ray.origin + depth * ray.direction;
        const glm::vec3 c = rays.cameraFrom(world);
        EXPECT_GT(c.z, 0.0f);
        EXPECT_NEAR(glm::length(c), depth, 1e-5f); // the camera's frame is orthonormal
        const glm::vec2 image = rays.imageFrom(c);
        EXPECT_NEAR(image.x, px, 1e-3f);
        EXPECT_NEAR(image.y, py, 1e-3f);
    }
}

TEST(Camera, TheLabCameraSeesTheLabLightAboveTheCentre) {
    // The lab's light (0, 0.5, -0.7) from (0, 0, -3): depth 2.3, 0.5 up, f = H = 500.
    const PrimaryRays rays(Camera{}, 500, 500);
    const glm::vec3 c = rays.cameraFrom({0.0f, 0.5f, -0.7f});
    expectVecNear(c, {0.0f, 0.5f, 2.3f}, 1e-6f);
    const glm::vec2 image = rays.imageFrom(c);
    EXPECT_NEAR(image.x, 250.0f, 1e-4f);
    EXPECT_NEAR(image.y, 250.0f - 500.0f * 0.5f / 2.3f, 1e-3f);
}

TEST(Camera, YawTurnsLeftAndPitchLooksUp) {
    Camera camera;
    camera.yawDegrees = 90.0f;
    expectVecNear(forwardOf(camera), {1.0f, 0.0f, 0.0f});
    expectVecNear(worldFromCamera(camera)[0], {0.0f, 0.0f, 1.0f});
    camera.yawDegrees = 0.0f;
    camera.pitchDegrees = 30.0f;
    expectVecNear(forwardOf(camera), {0.0f, 0.5f, std::sqrt(3.0f) / 2.0f});
    const glm::mat3 basis = worldFromCamera(camera);
    EXPECT_NEAR(glm::dot(basis[0], basis[1]), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(basis[1], basis[2]), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(basis[1]), 1.0f, 1e-6f);
    EXPECT_GT(basis[1].y, 0.0f);
}

TEST(Camera, LookAtPointsTheForwardAxisAtTheTarget) {
    Camera camera;
    camera.position = {1.0f, 2.0f, 3.0f};
    const glm::vec3 target{-2.0f, 0.5f, 7.0f};
    lookAt(camera, target);
    expectVecNear(forwardOf(camera), glm::normalize(target - camera.position), 1e-5f);
    // Straight down is clamped short of the pole, where yaw would be undefined.
    lookAt(camera, camera.position - glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_GT(camera.pitchDegrees, -90.0f);
    EXPECT_LT(camera.pitchDegrees, -89.0f);
    // The target at the camera changes nothing.
    const Camera before = camera;
    lookAt(camera, camera.position);
    EXPECT_EQ(camera.yawDegrees, before.yawDegrees);
    EXPECT_EQ(camera.pitchDegrees, before.pitchDegrees);
}

TEST(Camera, OrbitKeepsTheDistanceAndLooksAtThePivot) {
    Camera c;
    c.position = {0.3f, 0.4f, -3.0f};
    const glm::vec3 pivot(0.1f, -0.2f, 0.5f);
    const float distance = glm::length(pivot - c.position);
    orbitCamera(c, pivot, 30.0f, 10.0f);
    EXPECT_NEAR(glm::length(pivot - c.position), distance, 1e-4f);
    const glm::vec3 toPivot = glm::normalize(pivot - c.position);
    EXPECT_NEAR(glm::dot(forwardOf(c), toPivot), 1.0f, 1e-5f);
    // Round the pivot and back: where it started.
    Camera round = c;
    for (int i = 0; i < 12; ++i) {
        orbitCamera(round, pivot, 30.0f, 0.0f);
    }
    EXPECT_NEAR(glm::length(round.position - c.position), 0.0f, 1e-3f);
    // The pitch stops short of the pole.
    orbitCamera(c, pivot, 0.0f, 500.0f);
    EXPECT_LE(c.pitchDegrees, 85.0f + 1e-4f);
    EXPECT_NEAR(glm::length(pivot - c.position), distance, 1e-4f);
    // A camera at its pivot stays.
    Camera at;
    at.position = pivot;
    orbitCamera(at, pivot, 10.0f, 10.0f);
    EXPECT_EQ(at.position, pivot);
}

TEST(Camera, PanMovesAlongTheCamerasRightAndUp) {
    Camera c;
    c.yawDegrees = 40.0f;
    const glm::vec3 start = c.position;
    panCamera(c, 1.0f, 0.5f);
    const glm::vec3 moved = c.position - start;
    EXPECT_NEAR(glm::dot(moved, forwardOf(c)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(moved), std::sqrt(1.25f), 1e-5f);
    EXPECT_EQ(c.yawDegrees, 40.0f);
}

} // namespace
} // namespace raylab

namespace raylab {
namespace {

TEST(Camera, ATurntableTurnsTheCameraRigidlyAboutTheCentresVerticalLine) {
    Camera start;
    start.position = glm::vec3(0.3f, 0.4f, -2.5f);
    start.yawDegrees = 10.0f;
    start.pitchDegrees = -8.0f;
    const glm::vec3 centre(0.1f, -0.2f, 0.2f);
    const std::vector<Camera> frames = turntableCameras(start, centre, 12);
    ASSERT_EQ(frames.size(), 12u);
    EXPECT_EQ(frames[0].position, start.position);
    EXPECT_FLOAT_EQ(frames[0].yawDegrees, start.yawDegrees);
    // Any point, seen from the camera, stays where it was on every frame: a point fixed to the
    // turntable's axis (the centre, and one above it) keeps its camera-space coordinates.
    const auto inCamera = [](const Camera& c, const glm::vec3& p) {
        return glm::transpose(worldFromCamera(c)) * (p - c.position);
    };
    for (const glm::vec3& p : {centre, centre + glm::vec3(0.0f, 1.0f, 0.0f)}) {
        const glm::vec3 seen = inCamera(start, p);
        for (const Camera& frame : frames) {
            const glm::vec3 now = inCamera(frame, p);
            EXPECT_NEAR(now.x, seen.x, 1e-5f);
            EXPECT_NEAR(now.y, seen.y, 1e-5f);
            EXPECT_NEAR(now.z, seen.z, 1e-5f);
            EXPECT_FLOAT_EQ(frame.pitchDegrees, start.pitchDegrees);
            EXPECT_NEAR(frame.position.y, start.position.y, 1e-6f);
            EXPECT_NEAR(
                glm::length(glm::vec2(frame.position.x - centre.x, frame.position.z - centre.z)),
                glm::length(glm::vec2(start.position.x - centre.x, start.position.z - centre.z)),
                1e-5f);
        }
    }
    // Evenly spaced, a quarter turn every three frames, and the camera goes round once.
    const glm::vec3 quarter = frames[3].position - centre;
    const glm::vec3 offset = start.position - centre;
    EXPECT_NEAR(glm::dot(glm::vec2(quarter.x, quarter.z), glm::vec2(offset.x, offset.z)), 0.0f,
                1e-5f);
    EXPECT_NEAR(std::fabs(std::remainder(frames[6].yawDegrees - start.yawDegrees, 360.0f)), 180.0f,
                1e-4f);
}

} // namespace
} // namespace raylab
