// The SIMD traversal (8-wide nodes, 8-lane triangle tests) against the scalar reference.

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

// Same rays through both paths of one BVH: identical records, bit for bit.
void expectSimdEqualsScalar(const Scene& scene, const std::vector<Ray>& rays) {
    const Bvh bvh = buildBvh(scene);
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

TEST(BvhSimd, SoupRandomRays) {
    expectSimdEqualsScalar(makeTriangleSoup(20000, 0.05f, 2), makeRandomRays(20000, 3));
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
