// Edge cases of the BVH: empty and invalid input, duplicates, NaN rays, determinism.

#include "accel_check.h"
#include "accel_scenes.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <random>

namespace raylab::accel_test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// A scene of `count` copies of one triangle.
Scene copiesOf(const Triangle& triangle, std::size_t count) {
    Scene scene;
    scene.materials.push_back({});
    scene.triangles.assign(count, triangle);
    return scene;
}

TEST(BvhRobustness, EmptySceneNeverHits) {
    const Scene empty;
    const Bvh bvh = buildBvh(empty);
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_EQ(bvh.depth(), 0);
    for (const Ray& ray : makeRandomRays(100, 1)) {
        EXPECT_FALSE(closestHit(bvh, ray).found());
        EXPECT_FALSE(anyHit(bvh, ray));
        EXPECT_FALSE(closestHitScalar(bvh, ray).found());
    }
}

TEST(BvhRobustness, OneTriangleRepeated100000TimesGivesTheLowestIndex) {
    const Scene scene = copiesOf(
        Triangle{{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0}, 100000);
    const Bvh bvh = buildBvh(scene);
    EXPECT_LT(bvh.depth(), 64);
    const Ray ray{{0.1f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}};
    const Hit hit = closestHit(bvh, ray);
    EXPECT_EQ(hit.triangle, 0u);
    EXPECT_EQ(hit.t, 1.0f);
    EXPECT_TRUE(sameHit(closestHitScalar(bvh, ray), hit));
    EXPECT_TRUE(anyHit(bvh, ray));
    std::vector<Ray> rays = makeRandomRays(50, 2);
    expectMatchesBruteForce(scene, bvh, rays);
}

// Copies of one triangle in a plane of constant z lie in many leaves with flat boxes, whose
// planes' distances are rounded otherwise than the triangle test's t. From 1,000 units away
// those roundings outgrow the boxes' pad, and only the far distances' and the limit's round-up
// (bvh_box_ray.h) keep every box a hit lies in: each copy ties with the first found (the lowest
// index is the answer), a ray at a corner leaves a box where it enters it, and a ray whose range
// holds the hit's t alone must still enter its box. Without either round-up, in the scalar or
// the SIMD test, some of these rays miss.
TEST(BvhRobustness, FlatBoxesKeepEveryHitSeenFromFarAway) {
    const Triangle t{{-1.0f, -1.0f, 0.3f}, {1.0f, -1.0f, 0.3f}, {0.0f, 1.0f, 0.3f}, 0};
    const Scene scene = copiesOf(t, 256);
    const Bvh bvh = buildBvh(scene);
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Ray> rays;
    for (int i = 0; i < 2000; ++i) {
        // Half the rays mostly along x, so that the triangle test's axes are not the plane's.
        const float across = i % 2 == 0 ? 0.0f : -3.0f;
        const glm::vec3 origin(across + u(rng), u(rng), -1.0f + 0.7f * u(rng));
        const glm::vec3 target(0.5f * u(rng), -0.5f + 0.4f * u(rng), 0.3f);
        rays.push_back(Ray{origin, target - origin});
    }
    // From 1,000 units away, where the roundings of t outgrow the boxes' pad: there the plane's
    // distance exceeds the next float after t for about 1 ray in 8,000.
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 origin(300.0f * u(rng), 300.0f * u(rng), -1000.0f);
        const glm::vec3 target(0.5f * u(rng), -0.5f + 0.4f * u(rng), 0.3f);
        rays.push_back(Ray{origin, target - origin});
    }
    // From as far, at the corners and edges, where the boxes' sides meet the plane: there a
    // ray leaves a box as it enters it.
    const glm::vec3 edges[] = {t.v0, t.v1, t.v2, 0.5f * (t.v0 + t.v1), 0.5f * (t.v1 + t.v2)};
    for (int i = 0; i < 4000; ++i) {
        const glm::vec3 origin(300.0f * u(rng), 300.0f * u(rng), -1000.0f);
        rays.push_back(Ray{origin, edges[i % 5] - origin});
    }
    // The same rays with only the hit in range, (t-, t+): the box's plane against the limit.
    const std::size_t unlimited = rays.size();
    for (std::size_t i = 0; i < unlimited; ++i) {
        const Hit hit = closestHitBruteForce(scene, rays[i]);
        if (hit.found()) {
            Ray ray = rays[i];
            ray.tMin = std::nextafter(hit.t, 0.0f);
            ray.tMax = std::nextafter(hit.t, kInfinity);
            rays.push_back(ray);
        }
    }
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, rays), 45000);
    std::vector<Hit> hits(rays.size());
    closestHits(bvh, rays.data(), rays.size(), hits.data());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        ASSERT_TRUE(sameHit(hits[i], closestHitBruteForce(scene, rays[i]))) << "ray " << i;
    }
}

TEST(BvhRobustness, NonFiniteAndDegenerateTrianglesAreSkipped) {
    Scene scene = makeTriangleSoup(1000, 0.2f, 3);
    const float inf = kInfinity;
    scene.triangles[10].v0.x = kNaN;
    scene.triangles[20].v1.y = inf;
    scene.triangles[30].v2.z = -inf;
    scene.triangles[40].v1 = scene.triangles[40].v0; // zero area
    scene.triangles.push_back({{kNaN, kNaN, kNaN}, {kNaN, 0, 0}, {0, 0, kNaN}, 0});
    scene.triangles.push_back({{inf, inf, inf}, {-inf, -inf, -inf}, {inf, 0, 0}, 0});
    const Bvh bvh = buildBvh(scene);
    EXPECT_EQ(bvh.skippedTriangles, 6u);
    EXPECT_GE(bvh.leafReferences, scene.triangles.size() - 6); // pre-split copies may add some
    BvhBuildOptions noSplit;
    noSplit.presplitBudget = 0.0f;
    noSplit.spatialSplitBudget = 0.0f;
    EXPECT_EQ(buildBvh(scene, noSplit).leafReferences, scene.triangles.size() - 6);
    expectMatchesBruteForce(scene, bvh, makeRandomRays(2000, 4));

    Scene allBad;
    allBad.triangles.push_back({{kNaN, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0});
    const Bvh none = buildBvh(allBad);
    EXPECT_EQ(none.skippedTriangles, 1u);
    EXPECT_FALSE(closestHit(none, Ray{}).found());
}

TEST(BvhRobustness, NonFiniteRaysMissWithoutHanging) {
    const Scene scene = makeTriangleSoup(500, 0.3f, 5);
    const Bvh bvh = buildBvh(scene);
    const float inf = kInfinity;
    const std::vector<Ray> rays = {
        Ray{{kNaN, 0, 0}, {0, 0, 1}},          Ray{{0, 0, -3}, {kNaN, 0, 1}},
        Ray{{0, 0, -3}, {kNaN, kNaN, kNaN}},   Ray{{0, 0, -3}, {0, 0, 0}},
        Ray{{0, 0, -3}, {0, inf, 1}},          Ray{{inf, 0, -3}, {0, 0, 1}},
        Ray{{0, 0, -3}, {0, 0, 1}, kNaN, inf}, Ray{{0, 0, -3}, {0, 0, 1}, 0.0f, kNaN},
    };
    for (const Ray& ray : rays) {
        EXPECT_FALSE(closestHit(bvh, ray).found());
        EXPECT_FALSE(anyHit(bvh, ray));
        EXPECT_FALSE(closestHitScalar(bvh, ray).found());
        EXPECT_FALSE(anyHitScalar(bvh, ray));
    }
}

TEST(BvhRobustness, BuildIsTheSameForAnyThreadCount) {
    const Scene scene = makeTriangleSoup(60000, 0.02f, 6);
    BvhBuildOptions one, two, eight;
    one.threads = 1;
    two.threads = 2;
    eight.threads = 8;
    one.keepBinaryNodes = two.keepBinaryNodes = eight.keepBinaryNodes = true; // both forms
    const Bvh a = buildBvh(scene, one), b = buildBvh(scene, two), c = buildBvh(scene, eight);
    for (const Bvh* other : {&b, &c}) {
        ASSERT_EQ(a.nodes.size(), other->nodes.size());
        EXPECT_EQ(
            std::memcmp(a.nodes.data(), other->nodes.data(), a.nodes.size() * sizeof(BvhNode)), 0);
        ASSERT_EQ(a.leafReferences, other->leafReferences);
        ASSERT_EQ(a.triangles.size(), other->triangles.size());
        for (std::size_t i = 0; i < a.triangles.size(); ++i) {
            ASSERT_EQ(a.triangles[i].sceneIndex, other->triangles[i].sceneIndex);
        }
        ASSERT_EQ(a.triangleBlocks.size(), other->triangleBlocks.size());
        EXPECT_EQ(std::memcmp(a.triangleBlocks.data(), other->triangleBlocks.data(),
                              a.triangleBlocks.size() * sizeof(BvhTriangleBlock)),
                  0);
    }
    EXPECT_GE(a.leafReferences, 60000u); // pre-splitting may add copies
    EXPECT_LT(a.depth(), 64);
}

TEST(BvhRobustness, LeafSizeAndBinCountOptions) {
    const Scene scene = makeTriangleSoup(3000, 0.1f, 9);
    for (const int leaf : {1, 2, 8, 64}) {
        for (const int bins : {2, 16, 32}) {
            BvhBuildOptions options;
            options.maxLeafSize = leaf;
            options.binCount = bins;
            options.keepBinaryNodes = true;
            const Bvh bvh = buildBvh(scene, options);
            ASSERT_FALSE(bvh.nodes.empty());
            for (const BvhNode& node : bvh.nodes) {
                ASSERT_LE(node.count, static_cast<uint32_t>(leaf));
            }
            expectMatchesBruteForce(scene, bvh, makeRandomRays(300, 10));
        }
    }
}

} // namespace
} // namespace raylab::accel_test
