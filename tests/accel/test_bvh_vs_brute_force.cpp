// The BVH gives exactly brute force's answers: closest t, u, v, triangle, and any hit.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/camera.h"
#include "core/cornell_box.h"

#include <cmath>
#include <gtest/gtest.h>

namespace raylab::accel_test {
namespace {

TEST(BvhVsBruteForce, RandomTriangleSoups) {
    for (const uint32_t seed : {1u, 2u, 3u}) {
        const Scene scene = makeTriangleSoup(3000, 0.1f, seed);
        const Bvh bvh = buildBvh(scene);
        EXPECT_EQ(bvh.skippedTriangles, 0u);
        const int hits = expectMatchesBruteForce(scene, bvh, makeRandomRays(3000, seed + 10));
        EXPECT_GT(hits, 300);
    }
}

TEST(BvhVsBruteForce, LargeTrianglesOverlapping) {
    const Scene scene = makeTriangleSoup(500, 1.0f, 7);
    const Bvh bvh = buildBvh(scene);
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(3000, 8)), 1000);
}

TEST(BvhVsBruteForce, HeightField) {
    const Scene scene = makeHeightField(48, 5);
    const Bvh bvh = buildBvh(scene);
    std::vector<Ray> rays = makeRandomRays(3000, 6);
    // Straight down through the grid's vertices and edges too.
    for (int i = 0; i <= 48; ++i) {
        for (int j = 0; j <= 48; j += 3) {
            const float x = -1.0f + 2.0f * static_cast<float>(i) / 48.0f;
            const float y = -1.0f + 2.0f * static_cast<float>(j) / 48.0f;
            rays.push_back(Ray{{x, y, 2.0f}, {0.0f, 0.0f, -1.0f}});
        }
    }
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, rays), 1000);
}

TEST(BvhVsBruteForce, ClosedSphereFromInsideAlwaysHits) {
    const Scene scene = makeClosedSphere(24, 48, 1.0f, 0.1f, 11);
    const Bvh bvh = buildBvh(scene);
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Ray> rays;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 o(0.3f * u(rng), 0.3f * u(rng), 0.3f * u(rng));
        const glm::vec3 d(u(rng), u(rng), u(rng));
        if (glm::dot(d, d) > 0.0f) {
            rays.push_back(Ray{o, d});
        }
    }
    // Exactly at every vertex, from the centre.
    for (const Triangle& t : scene.triangles) {
        rays.push_back(Ray{glm::vec3(0.0f), t.v0});
    }
    EXPECT_EQ(expectMatchesBruteForce(scene, bvh, rays), static_cast<int>(rays.size()));
    for (const Ray& ray : rays) {
        ASSERT_TRUE(closestHit(bvh, ray).found());
        ASSERT_TRUE(anyHit(bvh, ray));
    }
}

TEST(BvhVsBruteForce, AxisAlignedRays) {
    const Scene soup = makeTriangleSoup(2000, 0.2f, 21);
    EXPECT_GT(expectMatchesBruteForce(soup, buildBvh(soup), makeAxisAlignedRays(3000, 1.2f, 22)),
              300);
    // The lab's box has axis-aligned walls, so these rays run inside its nodes' flat boxes.
    const Scene box = makeCornellBox();
    EXPECT_GT(expectMatchesBruteForce(box, buildBvh(box), makeAxisAlignedRays(3000, 0.99f, 23)),
              2500);
}

TEST(BvhVsBruteForce, ShadowRaysWithLimitJustBelowTheHit) {
    const Scene scene = makeTriangleSoup(2000, 0.15f, 31);
    const Bvh bvh = buildBvh(scene);
    std::vector<Ray> limited;
    for (Ray ray : makeRandomRays(3000, 32)) {
        const Hit hit = closestHitBruteForce(scene, ray);
        if (!hit.found()) {
            continue;
        }
        ray.tMax = std::nextafter(hit.t, 0.0f); // the hit is just out of range
        limited.push_back(ray);
        ray.tMax = hit.t; // still out: the bound is exclusive
        limited.push_back(ray);
        ray.tMax = std::nextafter(hit.t, kInfinity);
        ray.tMin = std::nextafter(hit.t, 0.0f); // only the hit is in range
        limited.push_back(ray);
    }
    ASSERT_GT(limited.size(), 600u);
    expectMatchesBruteForce(scene, bvh, limited);
    for (std::size_t i = 2; i < limited.size(); i += 3) {
        EXPECT_TRUE(anyHit(bvh, limited[i]));
    }
}

TEST(BvhVsBruteForce, CornellBoxCameraRays) {
    const Scene box = makeCornellBox();
    const Bvh bvh = buildBvh(box);
    const PrimaryRays camera(Camera{}, 100, 100);
    std::vector<Ray> rays;
    for (int y = 0; y < 100; ++y) {
        for (int x = 0; x < 100; ++x) {
            rays.push_back(
                camera.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
        }
    }
    EXPECT_EQ(expectMatchesBruteForce(box, bvh, rays), 10000);
}

} // namespace
} // namespace raylab::accel_test
