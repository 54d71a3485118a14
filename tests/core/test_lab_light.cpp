// The lab's light model against closed-form answers on an analytic scene: one large quad facing
// the camera, a point light, and (for shadows) a small square blocker.

#include "core/bvh/bvh.h"
#include "core/render/renderer.h"
#include "test_meshes.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace raylab {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kPlaneDepth = 3.0f;
const glm::vec3 kRho{0.6f, 0.4f, 0.2f};

RenderSettings analyticSettings() {
    RenderSettings s;
    s.camera.position = glm::vec3(0.0f);
    s.width = 64;
    s.height = 48;
    s.light.position = {0.3f, 0.8f, 1.0f};
    s.light.color = {1.0f, 0.5f, 0.25f};
    s.light.intensity = 5.0f;
    s.indirect = false;
    s.shadows = false;
    return s;
}

// Where the centre ray of pixel (x, y) meets the plane z = kPlaneDepth, in double precision.
glm::dvec3 planePoint(const RenderSettings& s, int x, int y) {
    const Ray ray = PrimaryRays(s.camera, s.width, s.height)
                        .through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    const glm::dvec3 o(ray.origin), d(ray.direction);
    return o + d * ((kPlaneDepth - o.z) / d.z);
}

// rho P cos(theta) / (4 pi r^2) for the plane, whose normal facing the camera is -z.
glm::dvec3 expectedDirect(const RenderSettings& s, const glm::dvec3& p) {
    const glm::dvec3 r = glm::dvec3(s.light.position) - p;
    const double r2 = glm::dot(r, r);
    const double cosine = std::max(0.0, -r.z / std::sqrt(r2));
    return glm::dvec3(kRho) * glm::dvec3(s.light.power()) * cosine / (4.0 * kPi * r2);
}

void expectRelativeNear(double actual, double expected, double relative, const char* what, int x,
                        int y) {
    EXPECT_NEAR(actual, expected, relative * std::abs(expected) + 1e-12)
        << what << " at pixel " << x << "," << y;
}

TEST(LabLight, EveryPixelOfALitQuadMatchesTheClosedForm) {
    const Scene scene = test::makeQuadScene(10.0f, kPlaneDepth, kRho);
    const RenderSettings s = analyticSettings();
    const Framebuffer image = render(scene, buildBvh(scene), s);
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const glm::dvec3 expected = expectedDirect(s, planePoint(s, x, y));
            const glm::vec3 got = image.at(x, y);
            ASSERT_GT(expected.x, 0.0);
            expectRelativeNear(got.x, expected.x, 1e-4, "red", x, y);
            expectRelativeNear(got.y, expected.y, 1e-4, "green", x, y);
            expectRelativeNear(got.z, expected.z, 1e-4, "blue", x, y);
        }
    }
}

TEST(LabLight, ABlockerDarkensExactlyItsGeometricShadow) {
    constexpr float blockerDepth = 2.0f;
    constexpr float blockerHalf = 0.3f;
    Scene scene = test::makeQuadScene(10.0f, kPlaneDepth, kRho);
    test::addSquareZ(scene, {0.0f, 0.0f, blockerDepth}, blockerHalf, 0);
    RenderSettings s = analyticSettings();
    s.shadows = true;
    const Bvh bvh = buildBvh(scene);
    const Framebuffer image = render(scene, bvh, s);
    const PrimaryRays rays(s.camera, s.width, s.height);

    int shadowed = 0, lit = 0;
    for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
            const Ray ray =
                rays.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            if (closestHit(bvh, ray).triangle >= 2) {
                continue; // the camera sees the blocker itself here
            }
            // Where the segment from the plane point to the light crosses the blocker's plane.
            const glm::dvec3 p = planePoint(s, x, y);
            const glm::dvec3 l(s.light.position);
            const glm::dvec3 q = p + (l - p) * ((blockerDepth - p.z) / (l.z - p.z));
            const double margin = blockerHalf - std::max(std::abs(q.x), std::abs(q.y));
            if (std::abs(margin) < 1e-4) {
                continue; // too close to the shadow's edge to call
            }
            const glm::vec3 got = image.at(x, y);
            if (margin > 0.0) {
                ++shadowed;
                EXPECT_EQ(got, glm::vec3(0.0f)) << "pixel " << x << "," << y;
            } else {
                ++lit;
                const glm::dvec3 expected = expectedDirect(s, p);
                expectRelativeNear(got.x, expected.x, 1e-4, "red", x, y);
                expectRelativeNear(got.z, expected.z, 1e-4, "blue", x, y);
            }
        }
    }
    EXPECT_GT(shadowed, 50);
    EXPECT_GT(lit, 1000);
}

TEST(LabLight, IndirectAddsExactlyRhoTimesN) {
    const Scene scene = test::makeQuadScene(10.0f, kPlaneDepth, kRho);
    const Bvh bvh = buildBvh(scene);
    RenderSettings s = analyticSettings();
    s.indirect = true;
    s.indirectColor = {0.5f, 1.0f, 0.25f};
    s.indirectIntensity = 0.8f;
    const glm::vec3 rhoN = kRho * (s.indirectColor * s.indirectIntensity);

    // With the light off, every pixel is exactly rho * N.
    RenderSettings dark = s;
    dark.light.intensity = 0.0f;
    for (const glm::vec3& p : render(scene, bvh, dark).pixels) {
        ASSERT_EQ(p, rhoN);
    }
    // With the light on, indirect adds rho * N to the direct part.
    RenderSettings off = s;
    off.indirect = false;
    const Framebuffer with = render(scene, bvh, s);
    const Framebuffer without = render(scene, bvh, off);
    for (std::size_t i = 0; i < with.pixels.size(); ++i) {
        const glm::vec3 added = with.pixels[i] - without.pixels[i];
        EXPECT_NEAR(added.x, rhoN.x, 1e-5f);
        EXPECT_NEAR(added.y, rhoN.y, 1e-5f);
        EXPECT_NEAR(added.z, rhoN.z, 1e-5f);
    }
}

TEST(LabLight, MissedRaysAreBlackAndSurfacesFacingAwayGetOnlyIndirect) {
    Scene scene = test::makeQuadScene(0.5f, kPlaneDepth, kRho);
    const Bvh bvh = buildBvh(scene);
    RenderSettings s = analyticSettings();
    s.indirect = true;
    s.light.position = {0.0f, 0.0f, 10.0f}; // behind the quad
    const Framebuffer image = render(scene, bvh, s);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.0f)); // a corner ray misses the small quad
    const glm::vec3 rhoN = kRho * s.indirect3();
    EXPECT_EQ(image.at(s.width / 2, s.height / 2), rhoN);
}

} // namespace
} // namespace raylab
