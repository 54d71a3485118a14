// The observer view without a window: where the observer starts, the lab camera's frustum and the
// light drawn over the observer's picture, clipping behind the observer, and switching cameras
// (each kept bit for bit, each with its own undo).

#include "core/cornell_box.h"
#include "core/scene.h"
#include "observer_geometry.h"
#include "observer_view.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

constexpr int kWidth = 320, kHeight = 240;

Aabb labBounds() { return makeCornellBox().bounds(); }

// Whether `observer` sees `world` in front of it and inside its kWidth x kHeight picture.
bool inView(const Camera& observer, const glm::vec3& world) {
    const PrimaryRays rays(observer, kWidth, kHeight);
    const glm::vec3 c = rays.cameraFrom(world);
    if (!(c.z > 0.0f)) {
        return false;
    }
    const glm::vec2 p = rays.imageFrom(c);
    return p.x >= 0.0f && p.x <= kWidth && p.y >= 0.0f && p.y <= kHeight;
}

std::vector<Camera> someLabCameras() {
    std::vector<Camera> cameras(4);
    cameras[1].position = {0.3f, -0.2f, -2.0f};
    cameras[1].yawDegrees = 20.0f;
    cameras[1].pitchDegrees = -10.0f;
    cameras[2].position = {2.5f, 1.5f, 1.0f};
    lookAt(cameras[2], glm::vec3(0.0f));
    cameras[3].position = {0.0f, 0.0f, -40.0f}; // far away
    cameras[3].verticalFovDegrees = 10.0f;
    return cameras;
}

TEST(ObserverGeometry, FrustumCornersLieOnTheCornerRaysAtThePlanesDepth) {
    Camera lab;
    lab.position = {0.3f, -0.2f, -2.0f};
    lab.yawDegrees = 20.0f;
    lab.pitchDegrees = -10.0f;
    const PrimaryRays rays(lab, kWidth, kHeight);
    const float depth = imagePlaneDistance(lab, labBounds());
    EXPECT_GT(depth, 0.0f);
    const auto corners = imagePlaneCorners(rays, kWidth, kHeight, depth);
    const glm::vec2 pixels[4] = {{0, 0}, {kWidth, 0}, {kWidth, kHeight}, {0, kHeight}};
    for (std::size_t i = 0; i < 4; ++i) {
        const Ray ray = rays.through(pixels[i].x, pixels[i].y);
        // On the corner ray: the direction from the camera to the corner is the ray's.
        const glm::vec3 along = glm::normalize(corners[i] - ray.origin);
        EXPECT_NEAR(glm::dot(along, ray.direction), 1.0f, 1e-6f) << i;
        // At the plane's depth, and seen at the picture's corner.
        const glm::vec3 c = rays.cameraFrom(corners[i]);
        EXPECT_NEAR(c.z, depth, 1e-5f) << i;
        const glm::vec2 seen = rays.imageFrom(c);
        EXPECT_NEAR(seen.x, pixels[i].x, 1e-2f) << i;
        EXPECT_NEAR(seen.y, pixels[i].y, 1e-2f) << i;
    }
    // The lab's camera and box: the plane is halfway to the box's centre, 1.5 units away, and
    // (focal length = height) its corners are at +-0.75 * width / height, +-0.75.
    const Camera labDefault;
    EXPECT_FLOAT_EQ(imagePlaneDistance(labDefault, labBounds()), 1.5f);
    const auto labCorners = imagePlaneCorners(PrimaryRays(labDefault, 100, 100), 100, 100, 1.5f);
    EXPECT_NEAR(labCorners[0].x, 0.75f, 1e-5f); // the picture's left is +x
    EXPECT_NEAR(labCorners[0].y, 0.75f, 1e-5f);
    EXPECT_NEAR(labCorners[0].z, -1.5f, 1e-5f);
    EXPECT_NEAR(labCorners[2].x, -0.75f, 1e-5f);
    EXPECT_NEAR(labCorners[2].y, -0.75f, 1e-5f);
}

TEST(ObserverGeometry, TheLabCameraSegmentsAreTheFrustumAndThePlanesOutline) {
    const Camera lab;
    const float depth = 1.5f;
    const auto corners =
        imagePlaneCorners(PrimaryRays(lab, kWidth, kHeight), kWidth, kHeight, depth);
    const std::vector<WorldSegment> segments =
        labCameraSegments(lab, kWidth, kHeight, depth, 0.05f);
    ASSERT_EQ(segments.size(), 11u); // 3 marker, 4 edges, 4 outline
    for (const WorldSegment& s : segments) {
        EXPECT_EQ(s.kind, OverlayRay::LabCamera);
    }
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(glm::length(segments[i].to - segments[i].from), 0.1f, 1e-6f);
        EXPECT_EQ(0.5f * (segments[i].from + segments[i].to), lab.position);
    }
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(segments[3 + i].from, lab.position);
        EXPECT_EQ(segments[3 + i].to, corners[i]);
        EXPECT_EQ(segments[7 + i].from, corners[i]);
        EXPECT_EQ(segments[7 + i].to, corners[(i + 1) % 4]);
    }
}

TEST(ObserverGeometry, TheObserverStartsSeeingTheLabCameraItsFrustumAndTheScene) {
    const Aabb bounds = labBounds();
    for (const Camera& lab : someLabCameras()) {
        const Camera observer = observerStart(lab, bounds);
        EXPECT_GT(observer.position.y, lab.position.y); // above
        // Further from the scene's centre than the lab camera: behind it.
        EXPECT_GT(glm::length(observer.position - bounds.center()),
                  glm::length(lab.position - bounds.center()));
        EXPECT_TRUE(inView(observer, lab.position)) << lab.position.z;
        EXPECT_TRUE(inView(observer, bounds.center()));
        // It looks at the scene's centre: the centre is in the middle of its picture.
        const PrimaryRays rays(observer, kWidth, kHeight);
        const glm::vec2 centre = rays.imageFrom(rays.cameraFrom(bounds.center()));
        EXPECT_NEAR(centre.x, 0.5f * kWidth, 0.5f);
        EXPECT_NEAR(centre.y, 0.5f * kHeight, 0.5f);
    }
    // The lab's camera: its whole frustum and image plane are in view too.
    const Camera lab;
    const Camera observer = observerStart(lab, bounds);
    for (const glm::vec3& corner : imagePlaneCorners(PrimaryRays(lab, kWidth, kHeight), kWidth,
                                                     kHeight, imagePlaneDistance(lab, bounds))) {
        EXPECT_TRUE(inView(observer, corner));
    }
    const std::vector<ImageSegment> drawn = observerOverlay(observer, kWidth, kHeight, lab, kWidth,
                                                            kHeight, PointLight(), bounds, 1e-3f);
    EXPECT_EQ(drawn.size(), 11u + 3u); // nothing of the lab camera or light clipped
}

TEST(ObserverGeometry, SegmentsBehindTheObserverAreClippedAtItsNearPlane) {
    // The observer looks along +z from the origin with a wide view; the lab camera stands
    // behind it.
    Camera observer;
    observer.position = glm::vec3(0.0f);
    observer.verticalFovDegrees = 120.0f;
    Camera lab;
    lab.position = {0.0f, 0.0f, -2.0f};
    const float nearDepth = 0.01f;
    const std::vector<WorldSegment> world =
        labCameraSegments(lab, kWidth, kHeight, 6.0f, 0.05f); // plane at z = 4, in front
    const std::vector<ImageSegment> drawn =
        projectSegments(PrimaryRays(observer, kWidth, kHeight), kWidth, kHeight, nearDepth, world);
    // The marker is wholly behind; the four edges are cut at the near plane; the outline stays.
    int edges = 0, outline = 0;
    for (const ImageSegment& s : drawn) {
        EXPECT_GE(s.from.x, 0.0f);
        EXPECT_LE(s.from.x, static_cast<float>(kWidth));
        EXPECT_GE(s.to.y, 0.0f);
        EXPECT_LE(s.to.y, static_cast<float>(kHeight));
    }
    for (std::size_t i = 0; i < world.size(); ++i) {
        ImageSegment s;
        const bool kept = projectSegment(PrimaryRays(observer, kWidth, kHeight), kWidth, kHeight,
                                         nearDepth, world[i], s);
        if (i < 3) {
            EXPECT_FALSE(kept) << "marker segment " << i << " is behind the observer";
        } else if (i < 7) {
            edges += kept ? 1 : 0;
        } else {
            outline += kept ? 1 : 0;
        }
    }
    EXPECT_EQ(outline, 4);
    EXPECT_EQ(edges, 4);
    EXPECT_EQ(drawn.size(), static_cast<std::size_t>(edges + outline));
    // An edge's part behind the near plane is gone: a point of depth nearDepth projects far from
    // the centre, so what is drawn of an edge reaches the picture's border.
    ImageSegment edge;
    ASSERT_TRUE(projectSegment(PrimaryRays(observer, kWidth, kHeight), kWidth, kHeight, nearDepth,
                               world[3], edge));
    const auto onBorder = [](const glm::vec2& p) {
        return p.x < 1e-3f || p.y < 1e-3f || p.x > kWidth - 1e-3f || p.y > kHeight - 1e-3f;
    };
    EXPECT_TRUE(onBorder(edge.from) || onBorder(edge.to));
}

TEST(ObserverGeometry, TheLightIsAMarkerAndACircleOfItsRadius) {
    PointLight light;
    light.position = {0.0f, 0.5f, -0.7f};
    const glm::vec3 viewer(0.0f, 2.0f, -6.0f);
    EXPECT_EQ(lightSegments(light, viewer, 0.05f).size(), 3u);
    light.radius = 0.2f;
    const std::vector<WorldSegment> segments = lightSegments(light, viewer, 0.05f);
    ASSERT_EQ(segments.size(), 3u + static_cast<std::size_t>(kLightCircleSegments));
    const glm::vec3 towards = glm::normalize(viewer - light.position);
    for (std::size_t i = 3; i < segments.size(); ++i) {
        EXPECT_EQ(segments[i].kind, OverlayRay::Light);
        EXPECT_NEAR(glm::length(segments[i].from - light.position), 0.2f, 1e-5f);
        EXPECT_NEAR(glm::dot(segments[i].from - light.position, towards), 0.0f, 1e-5f);
        EXPECT_EQ(segments[i].to, segments[i + 1 < segments.size() ? i + 1 : 3].from);
    }
}

TEST(ObserverView, SwitchingMovesTheObserverAndReturnsTheLabCameraBitForBit) {
    RenderSettings settings;
    settings.camera.position = {0.1f, -0.2f, -2.9f};
    settings.camera.yawDegrees = 1.0f / 3.0f;
    const Camera lab = settings.camera;
    ObserverView view(settings);
    view.toggle(settings, labBounds());
    ASSERT_TRUE(view.on());
    EXPECT_EQ(settings.camera, observerStart(lab, labBounds()));
    EXPECT_EQ(view.keptLabCamera(), lab);
    // Moving the observer (and the light) leaves the lab camera kept as it was.
    settings.camera.position.x += 0.5f;
    settings.light.position.y = 0.25f;
    const Camera moved = settings.camera;
    view.toggle(settings, labBounds());
    EXPECT_FALSE(view.on());
    EXPECT_EQ(settings.camera, lab);
    EXPECT_EQ(settings.light.position.y, 0.25f);
    EXPECT_FALSE(view.keptLabCamera().has_value());
    // The observer comes back where it was left.
    view.toggle(settings, labBounds());
    EXPECT_EQ(settings.camera, moved);
    view.leave(settings);
    EXPECT_FALSE(view.on());
    EXPECT_EQ(settings.camera, lab);
}

TEST(ObserverView, UndoMovesOnlyTheCameraBeingMoved) {
    using Clock = SettingsHistory::Clock;
    Clock::time_point t{};
    const auto later = [&t] { return t += std::chrono::seconds(1); };
    RenderSettings settings;
    const Camera lab = settings.camera;
    ObserverView view(settings);
    view.toggle(settings, labBounds());
    const Camera start = settings.camera;
    settings.camera.position.z -= 1.0f; // the observer steps back
    view.history().observe(settings, later());
    view.history().observe(settings, later());
    EXPECT_TRUE(view.history().undo(settings));
    EXPECT_EQ(settings.camera, start);
    EXPECT_FALSE(view.history().undo(settings)); // never back to the lab camera
    EXPECT_EQ(settings.camera, start);
    view.toggle(settings, labBounds());
    EXPECT_EQ(settings.camera, lab);
    EXPECT_FALSE(view.history().undo(settings)); // the lab camera never moved
    EXPECT_EQ(settings.camera, lab);
    // Started from a settings file of the observer view: on, each camera as recorded, and the lab
    // camera's history starts at the lab camera.
    RenderSettings fromFile;
    fromFile.camera.position = {1.0f, 2.0f, -7.0f};
    ObserverView started(fromFile, lab);
    EXPECT_TRUE(started.on());
    EXPECT_EQ(started.keptLabCamera(), lab);
    started.toggle(fromFile, labBounds());
    EXPECT_EQ(fromFile.camera, lab);
    EXPECT_FALSE(started.history().undo(fromFile));
    started.toggle(fromFile, labBounds());
    EXPECT_EQ(fromFile.camera.position, glm::vec3(1.0f, 2.0f, -7.0f));
    // A restored screenshot of the observer view: both cameras as recorded.
    Camera elsewhere;
    elsewhere.position = {1.0f, 2.0f, -7.0f};
    view.observe(lab, elsewhere, settings);
    EXPECT_TRUE(view.on());
    EXPECT_EQ(settings.camera, elsewhere);
    EXPECT_EQ(view.keptLabCamera(), lab);
}

} // namespace
} // namespace raylab::viewer
