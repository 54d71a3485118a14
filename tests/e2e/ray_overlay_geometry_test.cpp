// The inspected pixel's rays over the picture, without a window: which segments an inspection
// gives, and how they are clipped at the near plane and the picture's edges and projected with the
// tracer's camera.

#include "core/cornell_box.h"
#include "core/integrators/pixel_inspection.h"
#include "core/lights/emitters.h"
#include "inspected_pixel.h"
#include "ray_overlay_geometry.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

constexpr int kSize = 200;

void expectNear(const glm::vec2& a, const glm::vec2& b, float tolerance = 1e-3f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
}

TEST(RayOverlay, AHitGivesTheCameraRayAndTheShadowRayToTheLight) {
    PixelInspection p;
    p.hit = true;
    p.point = {0.2f, -1.0f, 0.3f};
    p.toLight = {-0.2f, 1.5f, -1.0f};
    p.distance = glm::length(p.toLight);
    p.shadowTested = true;
    const glm::vec3 origin(0.0f, 0.0f, -3.0f);
    const std::vector<WorldSegment> clear = inspectionSegments(p, origin);
    ASSERT_EQ(clear.size(), 2u);
    EXPECT_EQ(clear[0].kind, OverlayRay::Camera);
    EXPECT_EQ(clear[0].from, origin);
    EXPECT_EQ(clear[0].to, p.point);
    EXPECT_EQ(clear[1].kind, OverlayRay::ShadowClear);
    EXPECT_EQ(clear[1].to, p.point + p.toLight);

    // Blocked: it ends at the blocker, t along the unit ray towards the light.
    p.shadowed = true;
    p.blocker = ShadowBlocker{7, 0.5f};
    const std::vector<WorldSegment> blocked = inspectionSegments(p, origin);
    ASSERT_EQ(blocked.size(), 2u);
    EXPECT_EQ(blocked[1].kind, OverlayRay::ShadowBlocked);
    EXPECT_NEAR(glm::length(blocked[1].to - p.point), 0.5f, 1e-6f);
    EXPECT_NEAR(glm::dot(glm::normalize(blocked[1].to - p.point), p.toLight / p.distance), 1.0f,
                1e-6f);

    // Not traced (shadows off): no shadow ray. A miss: nothing.
    p.shadowTested = false;
    EXPECT_EQ(inspectionSegments(p, origin).size(), 1u);
    p.hit = false;
    EXPECT_TRUE(inspectionSegments(p, origin).empty());
}

TEST(RayOverlay, ThePathIsAPolylineThroughItsSurfaces) {
    PixelInspection p;
    p.hit = true;
    for (const glm::vec3& point :
         {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 1.0f, 0.0f)}) {
        PathVertexRecord vertex;
        vertex.point = point;
        p.path.push_back(vertex);
    }
    const std::vector<WorldSegment> segments = inspectionSegments(p, glm::vec3(0.0f, 0.0f, -3.0f));
    ASSERT_EQ(segments.size(), 3u); // the camera ray, then two path segments
    EXPECT_EQ(segments[1].kind, OverlayRay::Path);
    EXPECT_EQ(segments[1].from, p.path[0].point);
    EXPECT_EQ(segments[1].to, p.path[1].point);
    EXPECT_EQ(segments[2].from, p.path[1].point);
    EXPECT_EQ(segments[2].to, p.path[2].point);
}

TEST(RayOverlay, APointIsDrawnWhereThePixelsRaySeesIt) {
    // The lab's camera: any point on pixel (x, y)'s centre ray projects to (x + .5, y + .5).
    const PrimaryRays rays(Camera{}, kSize, kSize);
    const Ray ray = rays.through(150.5f, 40.5f);
    ImageSegment out;
    ASSERT_TRUE(projectSegment(
        rays, kSize, kSize, 1e-3f,
        {ray.origin + 2.0f * ray.direction, ray.origin + 3.0f * ray.direction, OverlayRay::Path},
        out));
    expectNear(out.from, {150.5f, 40.5f});
    expectNear(out.to, {150.5f, 40.5f});
    EXPECT_EQ(out.kind, OverlayRay::Path);
    // The lab's light, 0.5 above the axis at depth 2.3: above the centre.
    ASSERT_TRUE(projectSegment(rays, kSize, kSize, 1e-3f,
                               {{0.0f, 0.0f, 0.0f}, {0.0f, 0.5f, -0.7f}, OverlayRay::ShadowClear},
                               out));
    expectNear(out.from, {100.0f, 100.0f});
    expectNear(out.to, {100.0f, 100.0f - 200.0f * 0.5f / 2.3f});
}

TEST(RayOverlay, SegmentsAreClippedAtTheNearPlane) {
    const PrimaryRays rays(Camera{}, kSize, kSize); // at z = -3, looking along +z
    ImageSegment out;
    // Wholly behind the near plane: nothing.
    EXPECT_FALSE(projectSegment(rays, kSize, kSize, 0.1f,
                                {{0.0f, 0.0f, -4.0f}, {0.1f, 0.0f, -2.95f}, OverlayRay::Camera},
                                out));
    // From behind the camera to a point in front: what is left starts on the near plane (and is
    // then cut at the picture's edge), and its far end is where the point projects.
    const glm::vec3 front(0.5f, 0.2f, -1.0f);
    ASSERT_TRUE(projectSegment(rays, kSize, kSize, 0.1f,
                               {{0.0f, 0.0f, -5.0f}, front, OverlayRay::Camera}, out));
    const glm::vec2 far = rays.imageFrom(rays.cameraFrom(front));
    expectNear(out.to, far);
    // By hand: in the camera's frame the segment runs from (0, 0, -2) to (-0.5, 0.2, 2); it
    // meets depth 0.1 at (-0.2625, 0.105, 0.1), seen at (-425, -110) with f = 200, and the line
    // from there to (50, 80) enters the picture at its left edge, at (0, 60).
    expectNear(far, {50.0f, 80.0f});
    expectNear(out.from, {0.0f, 60.0f}, 1e-2f);
}

TEST(RayOverlay, SegmentsAreClippedToThePicture) {
    const PrimaryRays rays(Camera{}, kSize, kSize);
    ImageSegment out;
    // A horizontal line at depth 1 through the centre row, far wider than the view: x in [0, W].
    ASSERT_TRUE(projectSegment(rays, kSize, kSize, 1e-3f,
                               {{-10.0f, 0.0f, -2.0f}, {10.0f, 0.0f, -2.0f}, OverlayRay::Path},
                               out));
    EXPECT_NEAR(std::min(out.from.x, out.to.x), 0.0f, 1e-3f);
    EXPECT_NEAR(std::max(out.from.x, out.to.x), static_cast<float>(kSize), 1e-3f);
    EXPECT_NEAR(out.from.y, 100.0f, 1e-3f);
    // Wholly outside the view (far to the side): nothing.
    EXPECT_FALSE(projectSegment(rays, kSize, kSize, 1e-3f,
                                {{-10.0f, 0.0f, -2.0f}, {-9.0f, 0.0f, -2.0f}, OverlayRay::Path},
                                out));
}

TEST(RayOverlay, TheLabsShadowRaysProjectFromThePixelToTheLightOrTheBlocker) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    const EmitterTable emitters = buildEmitterTable(scene);
    RenderSettings settings;
    settings.width = kSize;
    settings.height = kSize;
    const PrimaryRays rays(settings.camera, kSize, kSize);
    const glm::vec2 light = rays.imageFrom(rays.cameraFrom(settings.light.position));
    int blockedSeen = 0;
    for (const auto& [x, y] : {std::pair{100, 190}, {60, 185}, {150, 170}, {30, 30}}) {
        const PixelInspection p = inspectPixel(scene, bvh, emitters, settings, x, y);
        ASSERT_TRUE(p.hit);
        const std::vector<ImageSegment> shown = projectSegments(
            rays, kSize, kSize, 1e-3f, inspectionSegments(p, settings.camera.position));
        ASSERT_EQ(shown.size(), 2u) << "pixel " << x << ", " << y;
        // The camera ray is seen end on: at the pixel's centre.
        expectNear(shown[0].from, {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f},
                   1e-2f);
        expectNear(shown[0].to, shown[0].from, 1e-2f);
        // The shadow ray starts there and heads for the light.
        expectNear(shown[1].from, shown[0].to, 1e-2f);
        if (p.blocker) {
            ++blockedSeen;
            EXPECT_EQ(shown[1].kind, OverlayRay::ShadowBlocked);
            const glm::vec2 way = shown[1].to - shown[1].from;
            const glm::vec2 all = light - shown[1].from;
            EXPECT_LT(glm::length(way), glm::length(all));
            EXPECT_GT(glm::dot(way, all), 0.0f);
        } else {
            EXPECT_EQ(shown[1].kind, OverlayRay::ShadowClear);
            expectNear(shown[1].to, light, 1e-2f);
        }
    }
    EXPECT_GT(blockedSeen, 0) << "none of the pixels is in a block's shadow";
}

TEST(RayOverlay, APinnedPixelKeepsItsCameraAndSizeAndFollowsTheOtherSettings) {
    RenderSettings picked;
    picked.width = 120;
    picked.height = 90;
    const InspectedPixel pixel{30, 40, picked.camera, picked.width, picked.height};
    EXPECT_TRUE(seenAsPicked(picked, pixel));
    RenderSettings now = picked;
    now.camera.position.z += 0.1f;
    now.width = 200;
    now.shadowEpsilon = 0.0f;
    EXPECT_FALSE(seenAsPicked(now, pixel));
    const RenderSettings used = inspectionSettings(now, pixel);
    EXPECT_EQ(used.camera, picked.camera);
    EXPECT_EQ(used.width, 120);
    EXPECT_EQ(used.height, 90);
    EXPECT_EQ(used.shadowEpsilon, 0.0f);
    now.camera = picked.camera;
    now.width = picked.width;
    EXPECT_TRUE(seenAsPicked(now, pixel));
}

TEST(RayOverlay, ColoursAreSaturatedAndDistinct) {
    const OverlayRay kinds[] = {OverlayRay::Camera, OverlayRay::ShadowClear,
                                OverlayRay::ShadowBlocked, OverlayRay::Path};
    for (const OverlayRay a : kinds) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(overlayColour(a)[c] == 0.0f || overlayColour(a)[c] == 1.0f);
        }
        for (const OverlayRay b : kinds) {
            EXPECT_EQ(a == b, overlayColour(a) == overlayColour(b));
        }
    }
}

TEST(RayOverlay, ALineQuadIsTwoTrianglesOfTheLinesWidth) {
    std::vector<glm::vec2> vertices;
    appendLineQuad({10.0f, 10.0f}, {20.0f, 10.0f}, 2.0f, vertices);
    ASSERT_EQ(vertices.size(), 6u);
    for (const glm::vec2& v : vertices) {
        EXPECT_TRUE(v.x == 10.0f || v.x == 20.0f);
        EXPECT_TRUE(v.y == 9.0f || v.y == 11.0f);
    }
    appendLineQuad({5.0f, 5.0f}, {5.0f, 5.0f}, 2.0f, vertices);
    EXPECT_EQ(vertices.size(), 6u); // a point draws nothing
}

} // namespace
} // namespace raylab::viewer
