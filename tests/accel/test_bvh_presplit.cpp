// Pre-split triangles (core/bvh_presplit.h): a triangle referenced from several leaves must still
// give brute force's answers on both paths, and the binary (scalar) and 8-wide (SIMD) forms of
// one BVH must agree bit for bit.

#include "accel_check.h"
#include "accel_scenes.h"

#include <gtest/gtest.h>
#include <random>

namespace raylab::accel_test {
namespace {

// Long thin triangles across [-1, 1]^3 in random diagonal directions, among small ones: the
// slivers' boxes are mostly empty, so they get most of the split budget.
Scene makeSlivers(int count, uint32_t seed) {
    Scene scene = makeTriangleSoup(count, 0.05f, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < count / 10; ++i) {
        const glm::vec3 a{unit(rng), unit(rng), unit(rng)};
        const glm::vec3 b{unit(rng), unit(rng), unit(rng)};
        const glm::vec3 side{unit(rng) * 0.01f, unit(rng) * 0.01f, unit(rng) * 0.01f};
        scene.triangles.push_back({a, b, a + side, 0});
    }
    return scene;
}

TEST(BvhPresplit, SliversAreSplitAndMatchBruteForce) {
    const Scene scene = makeSlivers(4000, 11);
    const Bvh bvh = buildBvh(scene);
    EXPECT_GT(bvh.leafReferences, scene.triangles.size()); // copies were made
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(6000, 12)), 500);
    expectMatchesBruteForce(scene, bvh, makeAxisAlignedRays(4000, 1.1f, 13));
}

TEST(BvhPresplit, LargeBudgetOnOneBigTriangle) {
    // One triangle spanning the scene and a few tiny ones: the big one is cut into many pieces.
    Scene scene = makeTriangleSoup(50, 0.01f, 14);
    scene.triangles.push_back({{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, -0.9f}, {1.0f, -1.0f, 1.0f}, 0});
    BvhBuildOptions options;
    options.presplitBudget = 4.0f;
    const Bvh bvh = buildBvh(scene, options);
    EXPECT_GT(bvh.leafReferences, scene.triangles.size() + 20);
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(6000, 15)), 1000);
}

TEST(BvhPresplit, ScalarOnlyBuildKeepsItsOwnTriangles) {
    const Scene scene = makeSlivers(2000, 16);
    BvhBuildOptions scalarOnly;
    scalarOnly.simd = false;
    const Bvh bvh = buildBvh(scene, scalarOnly);
    EXPECT_TRUE(bvh.wideNodes.empty());
    EXPECT_EQ(bvh.triangles.size(), bvh.leafReferences);
    expectMatchesBruteForce(scene, bvh, makeRandomRays(3000, 17));
}

TEST(BvhPresplit, WideFormHoldsTheOnlyTriangleCopy) {
    const Scene scene = makeSlivers(2000, 18);
    BvhBuildOptions options;
    options.keepBinaryNodes = true; // to read the blocks through the binary leaves
    const Bvh bvh = buildBvh(scene, options);
    if (bvh.wideNodes.empty()) {
        GTEST_SKIP() << "this CPU has no AVX2: only the scalar form exists";
    }
    EXPECT_TRUE(bvh.triangles.empty());
    // Every binary leaf triangle read through the blocks is a real scene triangle's vertices.
    for (const BvhNode& node : bvh.nodes) {
        for (uint32_t i = node.index; node.isLeaf() && i < node.index + node.count; ++i) {
            const BvhTriangle t = bvh.leafTriangle(i);
            ASSERT_LT(t.sceneIndex, scene.triangles.size());
            ASSERT_EQ(t.v0, scene.triangles[t.sceneIndex].v0);
            ASSERT_EQ(t.v2, scene.triangles[t.sceneIndex].v2);
        }
    }
}

} // namespace
} // namespace raylab::accel_test
