// CameraWalks (bvh_packet.h): how closestHit64 walks a tile's blocks of camera rays on a CPU with
// AVX2 but not AVX-512. The rule that chooses from the shared walk's leaves; both walks answer as
// single rays, bit for bit; the shared walk counts what the rule reads and the eight walks count
// nothing; and the rule's choice on a mesh whose triangles are small against a block (eight walks)
// and on one whose triangles are large (the shared walk).

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/bvh/bvh_packet.h"
#include "core/bvh/traverse/bvh_packet16_traverse.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/integrators/lab_shading.h"

#include <cstdint>
#include <gtest/gtest.h>
#include <vector>

namespace raylab::accel_test {
namespace {

TEST(CameraWalks, TheRuleWaitsForItsLeavesThenTakesEightWalksWhereFewPacketsShareALeaf) {
    EXPECT_FALSE(CameraWalks{}.eightWalks());
    constexpr uint64_t decide = CameraWalks::kLeavesToDecide;
    constexpr uint64_t share = CameraWalks::kPacketsSharingALeaf;
    // Too few leaves to decide: the shared walk, however few packets share them.
    EXPECT_FALSE((CameraWalks{decide - 1, decide - 1}.eightWalks()));
    // Enough: eight walks just below the threshold's average, the shared walk at it and above.
    EXPECT_TRUE((CameraWalks{decide, share * decide - 1}.eightWalks()));
    EXPECT_FALSE((CameraWalks{decide, share * decide}.eightWalks()));
    EXPECT_TRUE((CameraWalks{1000, share * 1000 - 1}.eightWalks()));
    EXPECT_FALSE((CameraWalks{1000, 8 * 1000}.eightWalks()));
    EXPECT_TRUE((CameraWalks{1000, 1000}.eightWalks()));
}

// The camera rays of the 8 x 8 block at (x0, y0) as closestHit64 takes them: packet k lane i is
// the pixel tilePixel(k, i).
void blockPackets(const PrimaryRays& primary, int x0, int y0, RayPacket* packets) {
    for (int k = 0; k < kPacketSize; ++k) {
        for (int i = 0; i < kPacketSize; ++i) {
            const BlockPixel p = tilePixel(k, i);
            packets[k].set(i, primary.through(static_cast<float>(x0 + p.x) + 0.5f,
                                              static_cast<float>(y0 + p.y) + 0.5f));
        }
    }
}

// What closestHit64 did over a tile's blocks.
struct TileWalks {
    CameraWalks walks;       // as left after the tile's last block
    int eightWalkBlocks = 0; // blocks walked as eight walks
    int hits = 0;            // lanes that found a triangle
};

// Traces the 8 x 8 blocks of the image's tile [x0, x0 + side) x [y0, y0 + side) with one
// CameraWalks carried from block to block, as the renderer's tile loop does, and expects every
// lane to be the single ray's closestHit. Before each block, when `forced` is given, the walks
// are set to it. Expects the counts to grow only where the shared walk is taken on this CPU's
// path, and then by 1 to 8 packets a leaf.
TileWalks traceTile(const Bvh& bvh, const Camera& camera, int width, int height, int x0, int y0,
                    int side, const CameraWalks* forced = nullptr) {
    const PrimaryRays primary(camera, width, height);
    const bool counts = !bvhPacket16Supported(); // the AVX-512 walk counts nothing
    TileWalks tile;
    int failures = 0;
    for (int by = y0; by < y0 + side; by += kPacketSize) {
        for (int bx = x0; bx < x0 + side; bx += kPacketSize) {
            RayPacket packets[kPacketSize];
            blockPackets(primary, bx, by, packets);
            if (forced != nullptr) {
                tile.walks = *forced;
            }
            const CameraWalks before = tile.walks;
            const bool eight = counts && before.eightWalks();
            tile.eightWalkBlocks += eight ? 1 : 0;
            HitPacket hits[kPacketSize];
            closestHit64(bvh, packets, hits, tile.walks);
            const uint64_t leaves = tile.walks.leaves - before.leaves;
            const uint64_t tests = tile.walks.packetLeafTests - before.packetLeafTests;
            if (eight || !counts) {
                EXPECT_EQ(leaves, 0u) << bx << ", " << by;
                EXPECT_EQ(tests, 0u) << bx << ", " << by;
            } else {
                EXPECT_GE(tests, leaves) << bx << ", " << by;
                EXPECT_LE(tests, 8 * leaves) << bx << ", " << by;
            }
            for (int k = 0; k < kPacketSize; ++k) {
                for (int i = 0; i < kPacketSize; ++i) {
                    const Hit expected = closestHit(bvh, packets[k].ray(i));
                    if (!sameHit(hits[k].hit(i), expected) && failures++ < 5) {
                        ADD_FAILURE() << "block " << bx << ", " << by << " lane " << k << "." << i
                                      << ": t=" << hits[k].hit(i).t << " against " << expected.t;
                    }
                    tile.hits += expected.found() ? 1 : 0;
                }
            }
        }
    }
    EXPECT_EQ(failures, 0);
    return tile;
}

// A height field of 2 x 240^2 triangles seen whole from above: a quad of two triangles is about
// 0.4 pixels wide at 128 x 128, so a block's packets part ways near the root.
Camera heightFieldFromAbove() {
    Camera camera;
    camera.position = {0.0f, 0.0f, -2.6f};
    return camera;
}

TEST(CameraWalks, EightWalksAndTheSharedWalkAnswerAsSingleRays) {
    const Scene field = makeHeightField(240, 7);
    const Bvh bvh = buildBvh(field);
    const CameraWalks eight{CameraWalks::kLeavesToDecide, CameraWalks::kLeavesToDecide};
    const CameraWalks shared{};
    for (const CameraWalks* forced : {&eight, &shared}) {
        const TileWalks tile = traceTile(bvh, heightFieldFromAbove(), 128, 128, 32, 32, 64, forced);
        EXPECT_GT(tile.hits, 64 * 64 / 2);
        EXPECT_EQ(tile.eightWalkBlocks, forced == &eight && !bvhPacket16Supported() ? 64 : 0);
    }
    const Scene box = makeCornellBox();
    const Bvh boxBvh = buildBvh(box);
    EXPECT_GT(traceTile(boxBvh, Camera{}, 64, 48, 0, 0, 48, &eight).hits, 48 * 48 / 2);
}

TEST(CameraWalks, SmallTrianglesTakeEightWalksLargeOnesKeepTheSharedWalk) {
    if (bvhPacket16Supported()) {
        GTEST_SKIP() << "this CPU has AVX-512F: its 16-ray packets always share the walk and "
                        "count nothing";
    }
    const Scene field = makeHeightField(240, 7);
    const Bvh bvh = buildBvh(field);
    // A 32 x 32 tile (16 blocks), the renderer's, inside the field's image.
    const TileWalks fine = traceTile(bvh, heightFieldFromAbove(), 128, 128, 48, 48, 32);
    EXPECT_GE(fine.walks.leaves, CameraWalks::kLeavesToDecide);
    EXPECT_LT(fine.walks.packetLeafTests, CameraWalks::kPacketsSharingALeaf * fine.walks.leaves);
    EXPECT_GT(fine.eightWalkBlocks, 8);
    // The box's 30 triangles are far larger than a block: its packets share nearly every leaf.
    const Scene box = makeCornellBox();
    const Bvh boxBvh = buildBvh(box);
    const TileWalks coarse = traceTile(boxBvh, Camera{}, 256, 192, 96, 64, 64);
    EXPECT_GE(coarse.walks.leaves, CameraWalks::kLeavesToDecide);
    EXPECT_GE(coarse.walks.packetLeafTests,
              CameraWalks::kPacketsSharingALeaf * coarse.walks.leaves);
    EXPECT_EQ(coarse.eightWalkBlocks, 0);
}

} // namespace
} // namespace raylab::accel_test
