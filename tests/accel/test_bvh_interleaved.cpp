// Interleaved closest-hit walks (closestHitsInterleaved) and closestHits, against closestHit on
// the same rays, bit for bit: the walks take the single ray's steps, only in turns.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/bvh/traverse/bvh_wide_traverse.h"
#include "core/cornell_box.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <unistd.h>
#include <vector>

namespace raylab::accel_test {
namespace {

// The rays' closest hits through closestHitsInterleaved and through closestHits equal
// closestHit's; returns how many hit.
int expectInterleavedEqualsSingle(const Bvh& bvh, const std::vector<Ray>& rays) {
    const Hit unwritten{-1.0f, 0.0f, 0.0f, 12345u};
    std::vector<Hit> interleaved(rays.size(), unwritten), batched(rays.size(), unwritten);
    closestHitsInterleaved(bvh, rays.data(), rays.size(), interleaved.data());
    closestHits(bvh, rays.data(), rays.size(), batched.data());
    int hits = 0, failures = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Hit single = closestHit(bvh, rays[i]);
        if (!sameHit(interleaved[i], single) || !sameHit(batched[i], single)) {
            if (++failures <= 5) {
                ADD_FAILURE() << "ray " << i << ": interleaved t " << interleaved[i].t
                              << " triangle " << interleaved[i].triangle << ", single t "
                              << single.t << " triangle " << single.triangle;
            }
        }
        hits += single.found() ? 1 : 0;
    }
    EXPECT_EQ(failures, 0);
    return hits;
}

Bvh wideBvh(const Scene& scene) {
    Bvh bvh = buildBvh(scene);
    if (bvh.wideNodes.empty()) {
        ADD_FAILURE() << "no 8-wide form";
    }
    return bvh;
}

TEST(BvhInterleaved, SoupRandomRaysWithSegmentsAndInvalidRays) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "this CPU has no AVX2: the interleaved walks run on the 8-wide form only";
    }
    const Bvh bvh = wideBvh(makeTriangleSoup(20000, 0.05f, 21));
    std::vector<Ray> rays = makeRandomRays(20000, 22);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 0; i < rays.size(); ++i) {
        switch (i % 7) {
        case 1: rays[i].tMin = -2.0f; break;                                     // reaching back
        case 2: rays[i].tMax = 1.0f + 0.01f * static_cast<float>(i % 50); break; // segments
        case 3: rays[i].direction = glm::vec3(0.0f); break; // invalid: no direction
        case 4: rays[i].origin.x = nan; break;              // invalid: not finite
        case 5: rays[i].tMax = nan; break;                  // invalid: NaN limit
        default: break;
        }
    }
    EXPECT_GT(expectInterleavedEqualsSingle(bvh, rays), 2000);
}

// Rays through vertices and edge midpoints: lanes with an edge function of exactly zero go to
// the scalar test inside the walks.
TEST(BvhInterleaved, RaysThroughVerticesAndEdges) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "this CPU has no AVX2: the interleaved walks run on the 8-wide form only";
    }
    const Scene sphere = makeClosedSphere(64, 128, 2.0f, 0.05f, 23);
    std::vector<Ray> rays;
    for (const Triangle& t : sphere.triangles) {
        rays.push_back(Ray{glm::vec3(0.0f), t.v0});
        rays.push_back(Ray{glm::vec3(0.0f), 0.5f * (t.v0 + t.v1)});
    }
    EXPECT_EQ(expectInterleavedEqualsSingle(wideBvh(sphere), rays), static_cast<int>(rays.size()));
    const std::vector<Ray> axisAligned = makeAxisAlignedRays(20000, 0.999f, 24);
    EXPECT_GT(expectInterleavedEqualsSingle(wideBvh(makeCornellBox()), axisAligned), 10000);
}

// Fewer rays than walks, one ray, none: every answer written, nothing beyond.
TEST(BvhInterleaved, FewerRaysThanWalks) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "this CPU has no AVX2: the interleaved walks run on the 8-wide form only";
    }
    const Bvh bvh = wideBvh(makeTriangleSoup(2000, 0.1f, 25));
    const std::vector<Ray> all = makeRandomRays(kInterleavedRays - 1, 26);
    for (std::size_t n = 0; n <= all.size(); ++n) {
        const Hit untouched{-1.0f, 0.0f, 0.0f, 12345u};
        std::vector<Hit> hits(n + 1, untouched);
        closestHitsInterleaved(bvh, all.data(), n, hits.data());
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_TRUE(sameHit(hits[i], closestHit(bvh, all[i]))) << n << " rays, ray " << i;
        }
        EXPECT_TRUE(sameHit(hits[n], untouched)) << n << " rays";
    }
}

// closestHits' rule: interleaved walks only where the 8-wide form takes more than the size given.
TEST(BvhInterleaved, InterleavesOnlyBvhsLargerThanTheSizeGiven) {
    constexpr std::size_t kFrom = std::size_t{4} << 20;
    Bvh bvh;
    EXPECT_FALSE(interleavesRays(bvh, 0)); // no 8-wide form
    const std::size_t nodes = kFrom / sizeof(BvhWideNode);
    ASSERT_EQ(nodes * sizeof(BvhWideNode), kFrom);
    bvh.wideNodes.resize(nodes);
    EXPECT_FALSE(interleavesRays(bvh, kFrom)); // exactly the size
    EXPECT_TRUE(interleavesRays(bvh, kFrom - 1));
    bvh.triangleBlocks.resize(1);
    EXPECT_TRUE(interleavesRays(bvh, kFrom));
    bvh.wideNodes.resize(nodes / 2);
    EXPECT_FALSE(interleavesRays(bvh, kFrom));
    bvh.triangleBlocks.resize(kFrom / 2 / sizeof(BvhTriangleBlock) + 1);
    EXPECT_TRUE(interleavesRays(bvh, kFrom)); // nodes and blocks together
    EXPECT_FALSE(interleavesRays(bvh, kFrom + sizeof(BvhTriangleBlock)));
    // The size closestHits uses: the level 3 cache's as the system reports it, or
    // kInterleaveWithoutCacheSize where it reports none.
    EXPECT_EQ(interleavesRays(bvh), interleavesRays(bvh, interleaveFromBytes()));
    EXPECT_FALSE(interleavesRays(buildBvh(makeCornellBox())));
}

TEST(BvhInterleaved, InterleavesFromTheCacheSizeReported) {
    EXPECT_EQ(interleaveFromBytes(300L << 20), std::size_t{300} << 20);
    EXPECT_EQ(interleaveFromBytes(32L << 20), std::size_t{32} << 20);
    EXPECT_EQ(interleaveFromBytes(0), kInterleaveWithoutCacheSize);  // glibc: unknown
    EXPECT_EQ(interleaveFromBytes(-1), kInterleaveWithoutCacheSize); // not supported
#if defined(_SC_LEVEL3_CACHE_SIZE)
    // closestHits' size is the one for the level 3 cache glibc reports.
    EXPECT_EQ(interleaveFromBytes(), interleaveFromBytes(sysconf(_SC_LEVEL3_CACHE_SIZE)));
#endif
}

// Without the 8-wide form closestHits is closestHit (the scalar walk) ray by ray.
TEST(BvhInterleaved, ClosestHitsWithoutTheWideForm) {
    BvhBuildOptions scalarOnly;
    scalarOnly.simd = false;
    const Bvh bvh = buildBvh(makeTriangleSoup(5000, 0.05f, 27), scalarOnly);
    ASSERT_TRUE(bvh.wideNodes.empty());
    const std::vector<Ray> rays = makeRandomRays(3000, 28);
    std::vector<Hit> hits(rays.size());
    closestHits(bvh, rays.data(), rays.size(), hits.data());
    int found = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        ASSERT_TRUE(sameHit(hits[i], closestHitScalar(bvh, rays[i]))) << i;
        found += hits[i].found() ? 1 : 0;
    }
    EXPECT_GT(found, 0);
}

} // namespace
} // namespace raylab::accel_test
