// Packets of 64 rays (closestHit64: one walk of the BVH for eight RayPackets) against single
// rays, the scalar reference and brute force: every lane's answer bit for bit, on both paths
// (the AVX-512 walk of four 16-ray packets, skipped on CPUs without it, and the AVX2 walk of eight
// 8-ray packets). What only 64-ray packets have: one frustum for all packets (valid, or not when
// their directions differ in sign), pairs or packets of different permutations, packets without
// lanes, 64-bit lane masks, and a pending child kept for some packets' lanes.

#include "accel_packet16_check.h"
#include "accel_packet_rays.h"
#include "accel_scenes.h"
#include "core/bvh/bvh_packet.h"
#include "core/bvh/traverse/bvh_packet16_traverse.h"
#include "core/cornell_box.h"
#include "core/integrators/lab_shading.h"

#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <random>
#include <string>

namespace raylab::accel_test {
namespace {

constexpr int kBlockSide = 8;

// Camera rays of a width x height image (multiples of 8) block of 8 x 8 pixels by block, each
// block's 64 rays in the order the renderer traces a full block (tilePixel: ray 8 k + i is lane i
// of packet k, each pair of packets a 4 x 4 tile).
std::vector<Ray> blockCameraRays(const Camera& camera, int width, int height) {
    const PrimaryRays primary(camera, width, height);
    std::vector<Ray> rays;
    for (int y0 = 0; y0 < height; y0 += kBlockSide) {
        for (int x0 = 0; x0 < width; x0 += kBlockSide) {
            for (int k = 0; k < kPacketSize; ++k) {
                for (int i = 0; i < kPacketSize; ++i) {
                    const BlockPixel p = tilePixel(k, i);
                    rays.push_back(primary.through(static_cast<float>(x0 + p.x) + 0.5f,
                                                   static_cast<float>(y0 + p.y) + 0.5f));
                }
            }
        }
    }
    return rays;
}

class BvhPacket64 : public ::testing::TestWithParam<Packet16Path> {
protected:
    void SetUp() override {
        if (GetParam() == Packet16Path::Avx512 && !bvhPacket16Supported()) {
            GTEST_SKIP() << "this CPU has no AVX-512F: the 64-ray AVX-512 walk is not tested "
                            "here (the two-packet path is)";
        }
    }
    int expectPackets(const Bvh& bvh, const std::vector<Ray>& rays,
                      const Scene* scene = nullptr) const {
        return expectPackets64(bvh, rays, GetParam(), scene);
    }
};

TEST_P(BvhPacket64, CameraBlocksOfTheBoxMatchBruteForce) {
    const Scene box = makeCornellBox();
    const Bvh bvh = buildBvh(box);
    const std::vector<Ray> rays = blockCameraRays(Camera{}, 64, 48);
    EXPECT_GT(expectPackets(bvh, rays, &box), static_cast<int>(rays.size()) / 2);
}

// A dense soup seen from inside and from outside: the camera blocks' lanes part ways at many
// triangle edges, so children are taken for some packets' lanes only.
TEST_P(BvhPacket64, CameraBlocksOfASoupMatchBruteForce) {
    const Scene soup = makeTriangleSoup(6000, 0.04f, 41);
    const Bvh bvh = buildBvh(soup);
    Camera outside;
    outside.position = {0.0f, 0.0f, -2.5f};
    EXPECT_GT(expectPackets(bvh, blockCameraRays(outside, 96, 64), &soup), 0);
    Camera inside;
    inside.position = {0.05f, -0.1f, 0.0f};
    inside.yawDegrees = 40.0f;
    EXPECT_GT(expectPackets(bvh, blockCameraRays(inside, 64, 64), &soup), 0);
}

TEST_P(BvhPacket64, RandomRaysMatchBruteForce) {
    const Scene soup = makeTriangleSoup(5000, 0.05f, 11);
    const Bvh bvh = buildBvh(soup);
    EXPECT_GT(expectPackets(bvh, makeRandomRays(4000, 12), &soup), 0);
}

// Packets whose rays differ in direction: lane by lane (every packet holds several
// permutations), run by run of 8 (pairs whose halves differ go their own way; packets whose
// directions differ in sign share no frustum), and shadow rays from the box's hits towards its
// light (every origin its own).
TEST_P(BvhPacket64, MixedPermutationsAndShadowRays) {
    const Scene soup = makeTriangleSoup(5000, 0.1f, 16);
    const Bvh bvh = buildBvh(soup);
    EXPECT_GT(expectPackets(bvh, mixedDirectionRays(3000, /*perLane=*/true, 17), &soup), 0);
    EXPECT_GT(expectPackets(bvh, mixedDirectionRays(3000, /*perLane=*/false, 18), &soup), 0);
    const Scene box = makeCornellBox();
    const Bvh boxBvh = buildBvh(box);
    const std::vector<Ray> shadows =
        shadowRaysOf(boxBvh, blockCameraRays(Camera{}, 64, 48), {0.0f, 0.5f, -0.7f});
    ASSERT_GE(shadows.size(), 1000u);
    EXPECT_GT(expectPackets(boxBvh, shadows, &box), 0);
}

TEST_P(BvhPacket64, InvalidRaysAndPartialPackets) {
    const Bvh bvh = buildBvh(makeCornellBox());
    std::vector<Ray> rays = blockCameraRays(Camera{}, 32, 32);
    invalidateEveryThird(rays);
    expectPackets(bvh, rays);
    const std::vector<Ray> camera = blockCameraRays(Camera{}, 16, 8);
    int failures = 0;
    for (int count = 1; count <= 64; count += 7) {
        expectPacket64(bvh, camera.data(), count, ~uint64_t{0}, GetParam(), nullptr, failures);
    }
    EXPECT_EQ(failures, 0);
}

// Lane masks with gaps, whole packets and pairs off, and none at all: the lanes in the mask
// answer as single rays, the others get Hit{} whatever they hold.
TEST_P(BvhPacket64, LaneMasksWithGaps) {
    const Bvh bvh = buildBvh(makeCornellBox());
    const std::vector<Ray> rays = blockCameraRays(Camera{}, 64, 48);
    std::mt19937_64 rng(23);
    int failures = 0;
    constexpr uint64_t kMasks[] = {0u,
                                   1u,
                                   uint64_t{1} << 63,
                                   0xffffu,
                                   0xffff0000ffff0000u,
                                   0x00ff00ff00ff00ffu,
                                   0x8000000100000001u,
                                   ~uint64_t{0}};
    for (int k = 0; k < 400; ++k) {
        const uint64_t mask = k < 8 ? kMasks[k] : rng() & rng();
        const std::size_t first = static_cast<std::size_t>(k % 48) * 64;
        expectPacket64(bvh, &rays[first], 64, mask, GetParam(), nullptr, failures);
    }
    EXPECT_EQ(failures, 0);
}

// Every triangle three times, the copies at far apart indices: each lane keeps the lowest index
// at equal t, in leaves tested triangle by triangle against a packet's lanes (camera blocks) or
// block by block against each lane's ray (random rays).
TEST_P(BvhPacket64, CoincidentTrianglesGiveTheLowestIndexInEveryLane) {
    const Scene scene = makeTripledSoup();
    const Bvh bvh = buildBvh(scene);
    Camera camera;
    camera.position = {0.0f, 0.0f, -2.5f};
    EXPECT_GT(expectPackets(bvh, blockCameraRays(camera, 64, 48), &scene), 0);
    EXPECT_GT(expectPackets(bvh, makeRandomRays(3000, 30), &scene), 0);
}

TEST_P(BvhPacket64, DegenerateAndNonFiniteTriangles) {
    const Scene scene = makeSoupWithDegenerateTriangles();
    const Bvh bvh = buildBvh(scene);
    Camera camera;
    camera.position = {0.0f, 0.0f, -2.5f};
    expectPackets(bvh, blockCameraRays(camera, 64, 48), &scene);
    expectPackets(bvh, makeRandomRays(2000, 4), &scene);
}

INSTANTIATE_TEST_SUITE_P(Paths, BvhPacket64,
                         ::testing::Values(Packet16Path::Avx512, Packet16Path::TwoPackets8),
                         packet16PathName);

} // namespace
} // namespace raylab::accel_test
