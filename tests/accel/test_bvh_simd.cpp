// The SIMD traversal (8-wide nodes, 8-lane triangle tests) against the scalar reference, which
// walks the binary nodes when they are kept and the 8-wide ones otherwise.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/cornell_box.h"

#include <gtest/gtest.h>

namespace raylab::accel_test {
namespace {

TEST(BvhSimd, BuiltWhenSupportedAndAskedFor) {
    const Scene scene = makeTriangleSoup(1000, 0.1f, 1);
    BvhBuildOptions scalarOnly;
    scalarOnly.simd = false;
    EXPECT_TRUE(buildBvh(scene, scalarOnly).wideNodes.empty());
    EXPECT_EQ(buildBvh(scene).wideNodes.empty(), !bvhSimdSupported());
}

TEST(BvhSimd, TheWideFormReplacesTheBinaryNodesUnlessAskedToKeepThem) {
    const Scene scene = makeTriangleSoup(5000, 0.05f, 12);
    const Bvh wideOnly = buildBvh(scene);
    if (wideOnly.wideNodes.empty()) {
        GTEST_SKIP() << "this CPU has no AVX2: only the binary form exists";
    }
    BvhBuildOptions keep;
    keep.keepBinaryNodes = true;
    const Bvh both = buildBvh(scene, keep);
    EXPECT_TRUE(wideOnly.nodes.empty());
    ASSERT_FALSE(both.nodes.empty());
    EXPECT_EQ(both.memoryBytes() - wideOnly.memoryBytes(), both.nodes.capacity() * sizeof(BvhNode));
    // The same tree otherwise, and the same box.
    EXPECT_EQ(wideOnly.wideNodes.size(), both.wideNodes.size());
    EXPECT_EQ(wideOnly.triangleBlocks.size(), both.triangleBlocks.size());
    EXPECT_EQ(wideOnly.bounds().lower, both.bounds().lower);
    EXPECT_EQ(wideOnly.bounds().upper, both.bounds().upper);
    for (int a = 0; a < 3; ++a) { // the boxes are rounded outwards
        EXPECT_LE(both.bounds().lower[a], scene.bounds().lower[a]);
        EXPECT_GE(both.bounds().upper[a], scene.bounds().upper[a]);
        EXPECT_NEAR(both.bounds().lower[a], scene.bounds().lower[a], 1e-5f);
        EXPECT_NEAR(both.bounds().upper[a], scene.bounds().upper[a], 1e-5f);
    }
    EXPECT_GT(wideOnly.depth(), 1);
    EXPECT_LT(wideOnly.depth(), both.depth()); // 8-wide levels, fewer than binary ones
}

// Same rays through the SIMD path and the scalar reference of one BVH, once walking the binary
// nodes and once the 8-wide ones: identical records, bit for bit.
void expectSimdEqualsScalar(const Scene& scene, const std::vector<Ray>& rays) {
    BvhBuildOptions keep;
    keep.keepBinaryNodes = true;
    for (const Bvh& bvh : {buildBvh(scene), buildBvh(scene, keep)}) {
        if (bvh.wideNodes.empty()) {
            GTEST_SKIP() << "this CPU has no AVX2: only the scalar path exists";
        }
        int hits = 0;
        for (const Ray& ray : rays) {
            const Hit simd = closestHit(bvh, ray);
            ASSERT_TRUE(sameHit(simd, closestHitScalar(bvh, ray)));
            ASSERT_EQ(anyHit(bvh, ray), anyHitScalar(bvh, ray));
            hits += simd.found() ? 1 : 0;
        }
        EXPECT_GT(hits, 0);
    }
}

TEST(BvhSimd, SoupRandomRays) {
    expectSimdEqualsScalar(makeTriangleSoup(20000, 0.05f, 2), makeRandomRays(20000, 3));
}

// Segments reaching back past their origins: the children's entry distances are negative too,
// which the order of the pushed children (by their distances' bits) must handle.
TEST(BvhSimd, SoupRaysWithNegativeTMin) {
    std::vector<Ray> rays = makeRandomRays(20000, 8);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        rays[i].tMin = -3.0f + 0.25f * static_cast<float>(i % 8);
        rays[i].tMax = i % 3 == 0 ? 1.5f : kInfinity;
    }
    expectSimdEqualsScalar(makeTriangleSoup(20000, 0.05f, 9), rays);
}

TEST(BvhSimd, SoupAxisAlignedRays) {
    expectSimdEqualsScalar(makeTriangleSoup(20000, 0.05f, 4), makeAxisAlignedRays(20000, 1.1f, 5));
}

TEST(BvhSimd, ClosedSphereFromInside) {
    std::vector<Ray> rays;
    const Scene sphere = makeClosedSphere(64, 128, 2.0f, 0.05f, 6);
    for (const Triangle& t : sphere.triangles) { // through vertices and edge midpoints
        rays.push_back(Ray{glm::vec3(0.0f), t.v0});
        rays.push_back(Ray{glm::vec3(0.0f), 0.5f * (t.v0 + t.v1)});
    }
    expectSimdEqualsScalar(sphere, rays);
}

TEST(BvhSimd, CornellBoxAxisAlignedRays) {
    expectSimdEqualsScalar(makeCornellBox(), makeAxisAlignedRays(20000, 0.999f, 7));
}

} // namespace
} // namespace raylab::accel_test
