// Packets of rays (bvh_packet.h) against single rays and the scalar reference: every lane's
// answer bit for bit, whatever the other lanes hold; in packets of 8 and of 16.

#include "accel_check.h"
#include "accel_packet16_check.h"
#include "accel_packet_rays.h"
#include "accel_scenes.h"
#include "core/bvh/bvh_packet.h"
#include "core/camera.h"
#include "core/cornell_box.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <limits>
#include <random>

namespace raylab::accel_test {
namespace {

// Traces `rays` in packets of `packetSize` consecutive rays (the last one partial) and expects
// each lane to equal closestHit, closestHitScalar, anyHit and anyHitScalar of its ray. Returns
// how many rays hit.
int expectPacketsEqualSingle(const Bvh& bvh, const std::vector<Ray>& rays,
                             int packetSize = kPacketSize) {
    int hits = 0, failures = 0;
    for (std::size_t first = 0; first < rays.size() && failures < 5; first += packetSize) {
        const int count = static_cast<int>(
            std::min<std::size_t>(static_cast<std::size_t>(packetSize), rays.size() - first));
        Hit packetHits[kPacketSize];
        bool occluded[kPacketSize];
        closestHit8(bvh, &rays[first], count, packetHits);
        anyHit8(bvh, &rays[first], count, occluded);
        for (int i = 0; i < count; ++i) {
            const Ray& ray = rays[first + static_cast<std::size_t>(i)];
            const Hit single = closestHit(bvh, ray);
            const bool ok = sameHit(packetHits[i], single) &&
                            sameHit(packetHits[i], closestHitScalar(bvh, ray)) &&
                            occluded[i] == anyHit(bvh, ray) &&
                            occluded[i] == anyHitScalar(bvh, ray);
            if (!ok) {
                ++failures;
                ADD_FAILURE() << "ray " << first + static_cast<std::size_t>(i)
                              << ": packet t=" << packetHits[i].t
                              << " tri=" << packetHits[i].triangle << " any=" << occluded[i]
                              << ", single t=" << single.t << " tri=" << single.triangle
                              << " any=" << anyHit(bvh, ray);
            }
            hits += single.found() ? 1 : 0;
        }
    }
    // The same rays in packets of 16, on every path this CPU has (accel_packet16_check.h).
    for (const Packet16Path path : packet16Paths()) {
        if (packetSize == kPacketSize) {
            EXPECT_EQ(expectPackets16(bvh, rays, path), hits);
        }
    }
    return hits;
}

TEST(BvhPacket, RandomSoupRandomRays) {
    const Bvh bvh = buildBvh(makeTriangleSoup(20000, 0.05f, 11));
    EXPECT_GT(expectPacketsEqualSingle(bvh, makeRandomRays(20000, 12)), 0);
}

TEST(BvhPacket, CoherentRaysIntoASoup) {
    // Rays from one point into a narrow cone: one permutation, overlapping paths.
    const Scene soup = makeTriangleSoup(20000, 0.05f, 13);
    const Bvh bvh = buildBvh(soup);
    Camera camera;
    camera.position = {0.2f, 0.1f, -3.0f};
    const std::vector<Ray> rays = cameraRays(camera, 96, 64);
    EXPECT_GT(expectPacketsEqualSingle(bvh, rays), 0);
    expectPacketsEqualSingle(bvh, shadowRaysOf(bvh, rays, {0.3f, 2.5f, -0.5f}));
}

TEST(BvhPacket, CornellBoxCameraAndShadowRays) {
    const Bvh bvh = buildBvh(makeCornellBox());
    const std::vector<Ray> rays = cameraRays(Camera{}, 120, 120);
    EXPECT_EQ(expectPacketsEqualSingle(bvh, rays), 120 * 120);
    const std::vector<Ray> shadows = shadowRaysOf(bvh, rays, {0.0f, 0.5f, -0.7f});
    EXPECT_GT(shadows.size(), 10000u);
    expectPacketsEqualSingle(bvh, shadows);
}

TEST(BvhPacket, CornellBoxAxisAlignedRays) {
    const Bvh bvh = buildBvh(makeCornellBox());
    expectPacketsEqualSingle(bvh, makeAxisAlignedRays(20000, 0.999f, 14));
}

TEST(BvhPacket, ClosedSphereFromInsideThroughVerticesAndEdges) {
    const Scene sphere = makeClosedSphere(64, 128, 2.0f, 0.05f, 15);
    const Bvh bvh = buildBvh(sphere);
    std::vector<Ray> rays;
    for (const Triangle& t : sphere.triangles) {
        rays.push_back(Ray{glm::vec3(0.0f), t.v0});
        rays.push_back(Ray{glm::vec3(0.0f), 0.5f * (t.v0 + t.v1)});
    }
    EXPECT_EQ(expectPacketsEqualSingle(bvh, rays), static_cast<int>(rays.size()));
}

TEST(BvhPacket, MixedPermutationsInOnePacket) {
    // Each packet holds rays along all six axis directions and diagonals, so lanes disagree
    // on kz and on the direction's sign.
    const Bvh bvh = buildBvh(makeTriangleSoup(5000, 0.1f, 16));
    const std::vector<Ray> rays = mixedDirectionRays(8000, /*perLane=*/true, 17);
    EXPECT_GT(expectPacketsEqualSingle(bvh, rays), 0);
}

TEST(BvhPacket, InvalidRaysInSomeLanes) {
    const Bvh bvh = buildBvh(makeTriangleSoup(5000, 0.1f, 18));
    std::vector<Ray> rays = makeRandomRays(4000, 19);
    invalidateEveryThird(rays);
    expectPacketsEqualSingle(bvh, rays);
}

TEST(BvhPacket, PartiallyFilledPackets) {
    const Bvh bvh = buildBvh(makeCornellBox());
    const std::vector<Ray> rays = cameraRays(Camera{}, 35, 21);
    for (int size = 0; size <= kPacketSize; ++size) {
        if (size > 0) {
            expectPacketsEqualSingle(bvh, rays, size);
        }
    }
    Hit untouched[kPacketSize];
    closestHit8(bvh, rays.data(), 0, untouched); // an empty packet does nothing
    EXPECT_FALSE(untouched[0].found());
}

// A RayPacket with gaps in its lanes (as the shadow rays of the lit hits are traced): the lanes
// in the mask answer as single rays, the others get Hit{} and no occlusion, whatever they hold.
TEST(BvhPacket, LaneMasksWithGaps) {
    const Bvh bvh = buildBvh(makeCornellBox());
    const std::vector<Ray> rays = cameraRays(Camera{}, 64, 32);
    int answered = 0;
    for (unsigned mask = 0; mask < 256; ++mask) {
        RayPacket packet;
        for (int i = 0; i < kPacketSize; ++i) {
            packet.set(i, rays[(mask * 37 + static_cast<unsigned>(i) * 5) % rays.size()]);
        }
        packet.lanes = mask;
        HitPacket hits;
        hits.set(0, Hit{1.0f, 0.5f, 0.5f, 3}); // stale contents must be overwritten
        closestHit8(bvh, packet, hits);
        const unsigned occluded = anyHit8(bvh, packet);
        EXPECT_EQ(occluded & ~mask, 0u);
        for (int i = 0; i < kPacketSize; ++i) {
            if ((mask >> i) & 1u) {
                const Ray ray = packet.ray(i);
                ASSERT_TRUE(sameHit(hits.hit(i), closestHitScalar(bvh, ray))) << mask;
                ASSERT_EQ(((occluded >> i) & 1u) != 0, anyHitScalar(bvh, ray)) << mask;
                ++answered;
            } else {
                ASSERT_FALSE(hits.hit(i).found()) << "lane " << i << " of mask " << mask;
            }
        }
    }
    EXPECT_EQ(answered, 256 * 4);
}

TEST(BvhPacket, ShadowRaysWithLimitsJustBelowTheHit) {
    const Bvh bvh = buildBvh(makeHeightField(64, 20));
    std::vector<Ray> rays = cameraRays(Camera{}, 64, 32);
    std::vector<Ray> limited;
    for (const Ray& ray : rays) {
        const Hit hit = closestHit(bvh, ray);
        Ray below = ray;
        below.tMax = hit.found() ? std::nextafter(hit.t, 0.0f) : 1.0f;
        limited.push_back(below);
        Ray at = ray;
        at.tMax = hit.found() ? hit.t : 2.0f;
        limited.push_back(at);
    }
    expectPacketsEqualSingle(bvh, limited);
}

TEST(BvhPacket, ScalarOnlyBvhStillAnswers) {
    BvhBuildOptions scalarOnly;
    scalarOnly.simd = false;
    const Bvh bvh = buildBvh(makeCornellBox(), scalarOnly);
    EXPECT_EQ(expectPacketsEqualSingle(bvh, cameraRays(Camera{}, 40, 40)), 40 * 40);
}

TEST(BvhPacket, EmptyScene) {
    const Bvh bvh = buildBvh(Scene{});
    EXPECT_EQ(expectPacketsEqualSingle(bvh, makeRandomRays(100, 21)), 0);
}

} // namespace
} // namespace raylab::accel_test
