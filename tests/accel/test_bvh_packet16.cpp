// Packets of 16 rays (closestHit16, anyHit16) against single rays, the scalar reference and
// brute force: every lane's answer bit for bit, on both paths: the AVX-512 packet (skipped on
// CPUs without it) and the two 8-ray packets of CPUs without it. What only 16-ray packets have:
// halves of different ray permutations, 16-bit lane masks, partial packets of 9 to 16 rays.
// (test_bvh_packet.cpp traces its ray sets in 16-ray packets on every path too.)

#include "accel_packet16_check.h"
#include "accel_packet_rays.h"
#include "accel_scenes.h"
#include "core/bvh/bvh_packet.h"
#include "core/bvh/traverse/bvh_packet16_traverse.h"
#include "core/cornell_box.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>

namespace raylab::accel_test {
namespace {

class BvhPacket16 : public ::testing::TestWithParam<Packet16Path> {
protected:
    void SetUp() override {
        if (GetParam() == Packet16Path::Avx512 && !bvhPacket16Supported()) {
            GTEST_SKIP() << "this CPU has no AVX-512F: the 16-ray AVX-512 packets are not tested "
                            "here (the two-packet path is)";
        }
    }
    int expectPackets(const Bvh& bvh, const std::vector<Ray>& rays, const Scene* scene = nullptr,
                      int size = kPacket16Size) const {
        return expectPackets16(bvh, rays, GetParam(), scene, size);
    }
};

TEST_P(BvhPacket16, RandomSoupRandomRaysMatchBruteForce) {
    const Scene soup = makeTriangleSoup(5000, 0.05f, 11);
    const Bvh bvh = buildBvh(soup);
    EXPECT_GT(expectPackets(bvh, makeRandomRays(4000, 12), &soup), 0);
}

TEST_P(BvhPacket16, MixedPermutationsWithinAndAcrossHalves) {
    const Scene soup = makeTriangleSoup(5000, 0.1f, 16);
    const Bvh bvh = buildBvh(soup);
    // Every lane its own direction; and halves that each share one, different per half.
    const std::vector<Ray> mixed = mixedDirectionRays(3000, /*perLane=*/true, 17);
    const std::vector<Ray> halves = mixedDirectionRays(3000, /*perLane=*/false, 18);
    EXPECT_GT(expectPackets(bvh, mixed, &soup), 0);
    EXPECT_GT(expectPackets(bvh, halves, &soup), 0);
}

TEST_P(BvhPacket16, PartiallyFilledPackets) {
    const Bvh bvh = buildBvh(makeCornellBox());
    const std::vector<Ray> rays = cameraRays(Camera{}, 35, 21);
    for (int size = 1; size <= kPacket16Size; ++size) {
        expectPackets(bvh, rays, nullptr, size);
    }
}

// Lane masks with gaps, including a whole half off: the lanes in the mask answer as single
// rays, the others get Hit{} and no occlusion, whatever they hold.
TEST_P(BvhPacket16, LaneMasksWithGaps) {
    const Bvh bvh = buildBvh(makeCornellBox());
    const std::vector<Ray> rays = cameraRays(Camera{}, 64, 32);
    std::mt19937 rng(23);
    int failures = 0;
    for (int k = 0; k < 600; ++k) {
        constexpr unsigned kMasks[] = {0u, 0xffu, 0xff00u, 0x8001u, 0x0100u, 0x0080u, 0xffffu};
        const unsigned mask = k < 7 ? kMasks[k] : rng() & 0xffffu;
        const std::size_t first = (static_cast<std::size_t>(k) * 37) % (rays.size() - 16);
        expectPacket16(bvh, &rays[first], kPacket16Size, mask, GetParam(), nullptr, failures);
    }
    EXPECT_EQ(failures, 0);
}

// Every triangle three times, the copies at far apart indices: each lane keeps the lowest index
// at equal t, whether its leaves are tested triangle by triangle against the lanes (coherent
// camera rays) or, with few lanes left in a leaf, block by block against each lane's ray
// (random rays).
TEST_P(BvhPacket16, CoincidentTrianglesGiveTheLowestIndexInEveryLane) {
    const Scene scene = makeTripledSoup();
    const Bvh bvh = buildBvh(scene);
    Camera camera;
    camera.position = {0.0f, 0.0f, -2.5f};
    EXPECT_GT(expectPackets(bvh, cameraRays(camera, 64, 48), &scene), 0);
    EXPECT_GT(expectPackets(bvh, makeRandomRays(3000, 30), &scene), 0);
}

TEST_P(BvhPacket16, DegenerateAndNonFiniteTriangles) {
    const Scene scene = makeSoupWithDegenerateTriangles();
    const Bvh bvh = buildBvh(scene);
    Camera camera;
    camera.position = {0.0f, 0.0f, -2.5f};
    expectPackets(bvh, cameraRays(camera, 64, 48), &scene);
    expectPackets(bvh, makeRandomRays(2000, 4), &scene);
}

// The shadow rays of the lab's box towards its light, in 16-ray packets: either path (the AVX-512
// one, or two 8-ray packets one after the other) leaves in a LastOccluder a triangle that one of a
// packet's occluded rays hits, and a remembered triangle (with the rest of its block, tested next)
// changes no answer: not for rays that stop just short of their first hit (which would hit it
// further on), nor when it names no block of this BVH. (expectPackets16 carries one from packet to
// packet through every suite here and in test_bvh_packet.cpp.)
TEST_P(BvhPacket16, LastOccluderChangesNoAnswer) {
    const Scene box = makeCornellBox();
    const Bvh bvh = buildBvh(box);
    const std::vector<Ray> shadows =
        shadowRaysOf(bvh, cameraRays(Camera{}, 64, 48), {0.0f, 0.5f, -0.7f});
    ASSERT_GE(shadows.size(), 1000u);
    int occludedPackets = 0, remembered = 0, failures = 0;
    for (std::size_t first = 0; first + kPacket16Size <= shadows.size(); first += kPacket16Size) {
        RayPacket packets[2];
        for (int i = 0; i < kPacket16Size; ++i) {
            packets[i / kPacketSize].set(i % kPacketSize, shadows[first + i]);
        }
        LastOccluder last;
        const unsigned occluded = anyHit16(bvh, packets[0], packets[1], GetParam(), &last);
        occludedPackets += occluded != 0 ? 1 : 0;
        // Nothing is left where no lane of a packet traversal was occluded (lanes of another ray
        // permutation than the packet's go their own way).
        if (last.block == LastOccluder::kNone) {
            continue;
        }
        // The remembered triangle is one that an occluded ray hits.
        ASSERT_LT(last.block, bvh.triangleBlocks.size());
        const uint32_t triangle = bvh.triangleBlocks[last.block].sceneIndex[last.slot];
        ASSERT_LT(triangle, box.triangles.size());
        EXPECT_TRUE(rememberedTriangleHit(bvh, last, &shadows[first], occluded))
            << "packet at ray " << first;
        ++remembered;
        // The same rays stopped just before their first hit: none is occluded, whatever is
        // remembered.
        std::vector<Ray> stopped(shadows.begin() + static_cast<std::ptrdiff_t>(first),
                                 shadows.begin() + static_cast<std::ptrdiff_t>(first) +
                                     kPacket16Size);
        for (Ray& ray : stopped) {
            const Hit hit = closestHit(bvh, ray);
            if (hit.found()) {
                ray.tMax = std::nextafter(hit.t, 0.0f);
            }
        }
        LastOccluder stale = last;
        expectPacket16(bvh, stopped.data(), kPacket16Size, 0xffffu, GetParam(), &box, failures,
                       &stale);
        LastOccluder elsewhere;
        elsewhere.block = static_cast<uint32_t>(bvh.triangleBlocks.size()) + 3;
        expectPacket16(bvh, &shadows[first], kPacket16Size, 0xffffu, GetParam(), &box, failures,
                       &elsewhere);
    }
    EXPECT_EQ(failures, 0);
    EXPECT_GT(occludedPackets, 10);
    EXPECT_GT(remembered, occludedPackets / 2);
}

// Shadow rays of neighbouring hits on a height field towards a light beyond its bounds on every
// axis: every direction has the same signs, so a frustum bounds each packet's lanes (the shadow
// rays' usual case), and the field's hills occlude more than half of them; the LastOccluder is
// carried from packet to packet.
TEST_P(BvhPacket16, ShadowRaysOfAHeightFieldMatchBruteForce) {
    const Scene field = makeHeightField(48, 41);
    const Bvh bvh = buildBvh(field);
    Camera camera;
    camera.position = {0.1f, -0.2f, -1.9f};
    const std::vector<Ray> rays = cameraRays(camera, 96, 64);
    for (const glm::vec3& light : {glm::vec3(1.6f, 1.4f, -0.6f), glm::vec3(-1.5f, 1.8f, -0.7f)}) {
        const std::vector<Ray> shadows = shadowRaysOf(bvh, rays, light);
        ASSERT_GE(shadows.size(), 3000u);
        const int occluded = expectPackets(bvh, shadows, &field);
        EXPECT_GT(occluded, static_cast<int>(shadows.size()) / 2);
        EXPECT_LT(occluded, static_cast<int>(shadows.size()));
    }
}

INSTANTIATE_TEST_SUITE_P(Paths, BvhPacket16,
                         ::testing::Values(Packet16Path::Avx512, Packet16Path::TwoPackets8),
                         packet16PathName);

} // namespace
} // namespace raylab::accel_test
