// Looking inside a pixel: inspectPixel's numbers against a tracer written here in double
// precision (the lab's camera, the 30 triangles, the lab's equation by hand), and against
// render() for the pixel's value.

#include "core/bvh/bvh.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/integrators/pixel_inspection.h"
#include "core/render/renderer.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <gtest/gtest.h>
#include <optional>

namespace raylab {
namespace {

using dvec3 = glm::dvec3;

struct DoubleHit {
    uint32_t triangle = kNoTriangle;
    double t = 0.0;
};

// The closest triangle on o + t d, tMin < t < tMax, by Moller and Trumbore in double.
DoubleHit closestDouble(const Scene& scene, dvec3 o, dvec3 d, double tMin, double tMax) {
    DoubleHit best;
    best.t = tMax;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& tri = scene.triangles[i];
        const dvec3 v0(tri.v0), e1 = dvec3(tri.v1) - v0, e2 = dvec3(tri.v2) - v0;
        const dvec3 p = glm::cross(d, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-14) {
            continue;
        }
        const dvec3 s = o - v0;
        const double u = glm::dot(s, p) / det;
        const dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(d, q) / det;
        const double t = glm::dot(e2, q) / det;
        if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > tMin && t < best.t) {
            best = {i, t};
        }
    }
    return best;
}

struct Expected {
    bool hit = false;
    uint32_t triangle = kNoTriangle;
    dvec3 point{0.0}, normal{0.0}, toLight{0.0};
    double cosTheta = 0.0;
    bool shadowed = false;
    dvec3 radiance{0.0};
};

// The lab's equation by hand for the centre of pixel (x, y).
Expected byHand(const Scene& scene, const RenderSettings& s, int x, int y) {
    Expected e;
    const double f = s.height; // the lab's focal length (the lab's field of view)
    // The camera's right, up and forward axes: for the lab's camera -x, +y and +z.
    const glm::dmat3 axes(worldFromCamera(s.camera));
    const dvec3 d = glm::normalize(axes[0] * (x + 0.5 - s.width / 2.0) +
                                   axes[1] * (s.height / 2.0 - y - 0.5) + axes[2] * f);
    const dvec3 o(s.camera.position);
    const DoubleHit hit = closestDouble(scene, o, d, 0.0, 1e30);
    if (hit.triangle == kNoTriangle) {
        return e;
    }
    e.hit = true;
    e.triangle = hit.triangle;
    e.point = o + hit.t * d;
    const Triangle& tri = scene.triangles[hit.triangle];
    e.normal = glm::normalize(glm::cross(dvec3(tri.v1 - tri.v0), dvec3(tri.v2 - tri.v0)));
    if (glm::dot(e.normal, d) > 0.0) {
        e.normal = -e.normal;
    }
    e.toLight = dvec3(s.light.position) - e.point;
    const double r = glm::length(e.toLight);
    e.cosTheta = glm::dot(e.toLight / r, e.normal);
    const double eps = s.shadowEpsilon;
    e.shadowed = closestDouble(scene, e.point, e.toLight / r, eps, r - eps).triangle != kNoTriangle;
    const dvec3 rho(scene.materials[tri.material].diffuse);
    const double direct =
        e.shadowed || e.cosTheta <= 0.0
            ? 0.0
            : s.light.intensity * e.cosTheta / (4.0 * 3.14159265358979323846 * r * r);
    e.radiance = rho * (direct + static_cast<double>(s.indirectIntensity));
    return e;
}

void expectNear(const glm::vec3& a, const dvec3& b, double tolerance, const char* what) {
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a[c], b[c], tolerance) << what << " [" << c << "]";
    }
}

class Inspection : public testing::Test {
protected:
    Scene scene = makeCornellBox();
    Bvh bvh = buildBvh(scene);
    EmitterTable emitters;
    RenderSettings settings;

    // Checks pixel (x, y) against the hand-computed lab equation and returns the inspection.
    PixelInspection check(int x, int y) {
        const PixelInspection p = inspectPixel(scene, bvh, emitters, settings, x, y);
        const Expected e = byHand(scene, settings, x, y);
        SCOPED_TRACE(testing::Message() << "pixel " << x << ", " << y);
        EXPECT_EQ(p.hit, e.hit);
        if (!p.hit || !e.hit) {
            return p;
        }
        EXPECT_EQ(p.triangle, e.triangle);
        expectNear(p.point, e.point, 1e-5, "point");
        expectNear(p.normal, e.normal, 1e-6, "normal");
        expectNear(p.toLight, e.toLight, 1e-5, "r");
        EXPECT_NEAR(p.distance, glm::length(e.toLight), 1e-5);
        EXPECT_NEAR(p.cosTheta, e.cosTheta, 1e-5);
        EXPECT_EQ(p.shadowed, e.shadowed);
        EXPECT_EQ(p.blocker.has_value(), e.shadowed);
        expectNear(p.rho, dvec3(scene.materials[scene.triangles[e.triangle].material].diffuse), 0.0,
                   "rho");
        expectNear(p.indirect, dvec3(0.5), 0.0, "N");
        expectNear(p.radiance, e.radiance, 1e-5, "R");
        EXPECT_FLOAT_EQ(p.shadowTMax, p.distance - settings.shadowEpsilon);
        // R is the pixel's first sample exactly as render() makes it.
        RenderSettings one = settings;
        one.samplesPerPixel = 1;
        const Framebuffer image = render(scene, bvh, one);
        EXPECT_EQ(p.radiance, image.at(x, y));
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(
                p.display[static_cast<std::size_t>(c)],
                static_cast<uint8_t>(std::lround(std::clamp(p.radiance[c], 0.0f, 1.0f) * 255.0f)));
        }
        return p;
    }
};

TEST_F(Inspection, AWallABlockTopAndAShadowedFloorPixelMatchTheLabsEquationByHand) {
    // The back wall (white) above the blocks, lit.
    const PixelInspection wall = check(250, 150);
    EXPECT_EQ(scene.triangles[wall.triangle].material, static_cast<uint32_t>(LabColor::White));
    EXPECT_FALSE(wall.shadowed);
    // Find a pixel on the short (red) block's top and one of the floor in its shadow.
    std::optional<std::pair<int, int>> top;
    std::optional<std::pair<int, int>> shadowedFloor;
    for (int y = 200; y < 500 && !(top && shadowedFloor); y += 7) {
        for (int x = 0; x < 500; x += 7) {
            const Expected e = byHand(scene, settings, x, y);
            const uint32_t material = e.hit ? scene.triangles[e.triangle].material : 99;
            if (!top && material == static_cast<uint32_t>(LabColor::Red) && e.normal.y > 0.99) {
                top = {{x, y}};
            }
            // Deep inside a shadow: its neighbours three pixels away are in it too.
            const auto inShadow = [&](int px, int py) {
                const Expected n = byHand(scene, settings, px, py);
                return n.hit && n.triangle < 2 && n.shadowed;
            };
            if (!shadowedFloor && inShadow(x, y) && inShadow(x - 3, y) && inShadow(x + 3, y) &&
                inShadow(x, y - 3) && inShadow(x, y + 3)) {
                shadowedFloor = {{x, y}};
            }
        }
    }
    ASSERT_TRUE(top && shadowedFloor);
    check(top->first, top->second);
    const PixelInspection floor = check(shadowedFloor->first, shadowedFloor->second);
    ASSERT_TRUE(floor.shadowed);
    ASSERT_TRUE(floor.blocker);
    EXPECT_GE(floor.blocker->triangle, 10u); // a block's triangle
    EXPECT_GT(floor.blocker->t, settings.shadowEpsilon);
    EXPECT_LT(floor.blocker->t, floor.shadowTMax);
    expectNear(floor.direct, dvec3(0.0), 0.0, "D in shadow");
    EXPECT_GT(floor.directUnshadowed.x, 0.0f);
}

TEST_F(Inspection, AnAcnePixelAtEpsilonZeroIsBlockedByItsOwnTriangleNearZero) {
    settings.shadowEpsilon = 0.0f;
    int acne = 0;
    for (int y = 300; y < 500 && acne == 0; y += 3) {
        for (int x = 0; x < 500; x += 3) {
            const PixelInspection p = inspectPixel(scene, bvh, emitters, settings, x, y);
            if (p.hit && p.blocker && p.blocker->triangle == p.triangle) {
                EXPECT_LT(p.blocker->t, 1e-4f);
                EXPECT_TRUE(p.shadowed);
                // Black but for the constant: R = rho * N.
                EXPECT_EQ(p.radiance, p.rho * settings.indirect3());
                // With the lab's epsilon the same pixel is lit.
                RenderSettings lab;
                EXPECT_FALSE(inspectPixel(scene, bvh, emitters, lab, x, y).blocker.has_value());
                ++acne;
                break;
            }
        }
    }
    EXPECT_EQ(acne, 1);
}

TEST_F(Inspection, AMissSaysSoAndNothingElse) {
    settings.camera.yawDegrees = 180.0f; // looking away from the box, out of its opening
    const PixelInspection p = check(250, 250);
    EXPECT_FALSE(p.hit);
    EXPECT_EQ(p.triangle, kNoTriangle);
}

TEST_F(Inspection, ASphereLightGivesAPartialVisibilityInThePenumbra) {
    settings.light.radius = 0.2f;
    int partial = 0;
    for (int y = 300; y < 500; y += 5) {
        for (int x = 0; x < 500; x += 5) {
            const PixelInspection p = inspectPixel(scene, bvh, emitters, settings, x, y);
            EXPECT_GE(p.visibility, 0.0f);
            EXPECT_LE(p.visibility, 1.0f);
            partial += p.visibility > 0.05f && p.visibility < 0.95f ? 1 : 0;
        }
    }
    EXPECT_GT(partial, 10);
}

TEST_F(Inspection, ThePathIntegratorListsItsPathAndSumsIt) {
    settings.integrator = Integrator::Path;
    const PixelInspection p = inspectPixel(scene, bvh, emitters, settings, 250, 300);
    ASSERT_TRUE(p.hit);
    ASSERT_GE(p.path.size(), 2u);
    glm::vec3 sum(0.0f);
    for (const PathVertexRecord& v : p.path) {
        sum += v.adds;
    }
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(sum[c], p.radiance[c], 1e-5f * (1.0f + p.radiance[c]));
    }
    expectNear(p.path[0].point, dvec3(p.point), 0.0, "first vertex");
}

} // namespace
} // namespace raylab
