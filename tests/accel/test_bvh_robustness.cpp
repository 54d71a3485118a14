// Edge cases of the BVH: empty and invalid input, duplicates, NaN rays, determinism.

#include "accel_check.h"
#include "accel_scenes.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>

namespace raylab::accel_test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

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
    Scene scene;
    scene.materials.push_back({});
    const Triangle t{{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0};
    scene.triangles.assign(100000, t);
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
