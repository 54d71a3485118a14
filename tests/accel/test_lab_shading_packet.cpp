// shadeLab8 (packets of camera and shadow rays) against shadeLab, pixel for pixel.

#include "accel_scenes.h"
#include "core/bvh/bvh_frustum.h"
#include "core/bvh/bvh_packet.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/integrators/lab_shading.h"

#include <cstring>
#include <gtest/gtest.h>

namespace raylab::accel_test {
namespace {

void expectPacketShadingEqualsSingle(const Scene& scene, RenderSettings settings) {
    const Bvh bvh = buildBvh(scene);
    const PrimaryRays primary(settings.camera, settings.width, settings.height);
    RayCounts single, packets;
    for (int y = 0; y < settings.height; ++y) {
        for (int x0 = 0; x0 < settings.width; x0 += 8) {
            const int count = std::min(8, settings.width - x0);
            Ray rays[8];
            glm::vec3 radiance[8];
            for (int i = 0; i < count; ++i) {
                rays[i] = primary.through(static_cast<float>(x0 + i) + 0.5f,
                                          static_cast<float>(y) + 0.5f);
            }
            shadeLab8(scene, bvh, settings, rays, count, radiance, packets);
            for (int i = 0; i < count; ++i) {
                const glm::vec3 expected = shadeLab(scene, bvh, settings, rays[i], single);
                ASSERT_EQ(std::memcmp(&expected, &radiance[i], sizeof(glm::vec3)), 0)
                    << "pixel " << x0 + i << ", " << y;
            }
        }
    }
    EXPECT_EQ(packets.primary, single.primary);
    EXPECT_EQ(packets.shadow, single.shadow);
}

TEST(LabShadingPacket, CornellBoxWithAndWithoutShadows) {
    RenderSettings settings;
    settings.width = 101; // not a multiple of 8: partial packets at the row ends
    settings.height = 64;
    expectPacketShadingEqualsSingle(makeCornellBox(), settings);
    settings.shadows = false;
    expectPacketShadingEqualsSingle(makeCornellBox(), settings);
    settings.shadows = true;
    settings.shadowEpsilon = 0.0f; // shadow acne: self-hits at t just above 0
    expectPacketShadingEqualsSingle(makeCornellBox(), settings);
}

TEST(LabShadingPacket, SoupSeenFromOutside) {
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.light.position = {0.5f, 2.0f, -1.5f};
    expectPacketShadingEqualsSingle(makeTriangleSoup(5000, 0.1f, 31), settings);
}

// Packets whose lanes have gaps: the lanes outside the mask are black and not counted, whatever
// they hold; the others are shadeLab's.
TEST(LabShadingPacket, LaneMasksWithGaps) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings settings;
    const PrimaryRays primary(settings.camera, 64, 64);
    int lit = 0;
    for (unsigned mask = 0; mask < 256; ++mask) {
        RayPacket packet;
        for (int i = 0; i < kPacketSize; ++i) {
            packet.set(i, primary.through(static_cast<float>((mask * 7 + i * 9) % 64) + 0.5f,
                                          static_cast<float>((mask * 3 + i) % 64) + 0.5f));
        }
        packet.lanes = mask;
        RadiancePacket radiance;
        RayCounts packets, single;
        shadeLab8(scene, bvh, settings, packet, radiance, packets);
        for (int i = 0; i < kPacketSize; ++i) {
            const glm::vec3 value(radiance.value[0][i], radiance.value[1][i], radiance.value[2][i]);
            if ((mask >> i) & 1u) {
                const glm::vec3 expected = shadeLab(scene, bvh, settings, packet.ray(i), single);
                ASSERT_EQ(std::memcmp(&expected, &value, sizeof(glm::vec3)), 0) << mask;
                lit += value.x > 0.0f ? 1 : 0;
            } else {
                ASSERT_EQ(value, glm::vec3(0.0f)) << "lane " << i << " of mask " << mask;
            }
        }
        ASSERT_EQ(packets.primary, single.primary);
        ASSERT_EQ(packets.shadow, single.shadow);
    }
    EXPECT_GT(lit, 500);
}

// shadeLabBlock (a block's packets traced together as `tracing` says: through frustum
// candidates, fitted to the rays or from the block's image rectangle, or packet by packet)
// against shadeLab8 packet by packet: blocks of 1 to 8 rows, rows of 1 to 8 lanes, lanes with
// gaps, with and without shadows, for the box and a soup of 5,000 triangles.
void expectBlockShadingEqualsPackets(const Scene& scene, RenderSettings settings,
                                     BlockTracing tracing) {
    const Bvh bvh = buildBvh(scene);
    const PrimaryRays primary(settings.camera, settings.width, settings.height);
    int lit = 0;
    unsigned pattern = 0;
    for (int y0 = 0; y0 < settings.height; y0 += kPacketSize) {
        for (int x0 = 0; x0 < settings.width; x0 += kPacketSize) {
            ++pattern;
            const int rows = 1 + static_cast<int>(pattern % kPacketSize);
            RayPacket packets[kPacketSize];
            for (int r = 0; r < rows; ++r) {
                for (int i = 0; i < kPacketSize; ++i) {
                    packets[r].set(i, primary.through(static_cast<float>(x0 + i) + 0.25f,
                                                      static_cast<float>(y0 + r) + 0.75f));
                }
                // Full rows mostly; now and then a partial row or a mask with gaps.
                packets[r].lanes = (pattern + static_cast<unsigned>(r)) % 5 == 0
                                       ? (pattern * 37u + static_cast<unsigned>(r)) & 0xffu
                                       : 0xffu;
            }
            RadiancePacket block[kPacketSize], framed[kPacketSize], single[kPacketSize];
            RayCounts blockCounts, framedCounts, singleCounts;
            shadeLabBlock(scene, bvh, settings, packets, rows, block, blockCounts, tracing);
            // As the renderer calls it: the camera rays' frustum from the block's pixels.
            const ImageRect rect{static_cast<float>(x0), static_cast<float>(y0),
                                 static_cast<float>(x0 + kPacketSize),
                                 static_cast<float>(y0 + rows)};
            shadeLabBlock(scene, bvh, settings, primary, rect, packets, rows, framed, framedCounts,
                          tracing);
            for (int r = 0; r < rows; ++r) {
                shadeLab8(scene, bvh, settings, packets[r], single[r], singleCounts);
                ASSERT_EQ(std::memcmp(&block[r], &single[r], sizeof(RadiancePacket)), 0)
                    << "block " << x0 << ", " << y0 << " row " << r;
                ASSERT_EQ(std::memcmp(&framed[r], &single[r], sizeof(RadiancePacket)), 0)
                    << "block " << x0 << ", " << y0 << " row " << r << " (image rectangle)";
                for (int i = 0; i < kPacketSize; ++i) {
                    lit += block[r].value[0][i] > 0.0f ? 1 : 0;
                }
            }
            ASSERT_EQ(blockCounts.primary, singleCounts.primary);
            ASSERT_EQ(blockCounts.shadow, singleCounts.shadow);
            ASSERT_EQ(framedCounts.primary, singleCounts.primary);
            ASSERT_EQ(framedCounts.shadow, singleCounts.shadow);
        }
    }
    EXPECT_GT(lit, settings.width * settings.height / 4);
}

TEST(LabShadingPacket, BlocksEqualPackets) {
    for (const BlockTracing tracing :
         {BlockTracing::ForScene, BlockTracing::Frustums, BlockTracing::Packets}) {
        RenderSettings settings;
        settings.width = 96;
        settings.height = 72;
        expectBlockShadingEqualsPackets(makeCornellBox(), settings, tracing);
        settings.shadowEpsilon = 0.0f;
        expectBlockShadingEqualsPackets(makeCornellBox(), settings, tracing);
        settings.shadows = false;
        expectBlockShadingEqualsPackets(makeCornellBox(), settings, tracing);
        settings.shadows = true;
        settings.light.position = {0.5f, 2.0f, -1.5f};
        expectBlockShadingEqualsPackets(makeTriangleSoup(5000, 0.1f, 31), settings, tracing);
    }
}

// A mesh's full blocks (packets of 16 and 64 rays) framed so that some see only the background,
// which shadeLabBlock answers from their image rectangle (imageRectMissesScene) without tracing:
// every row's radiance and the ray counts are shadeLab8's, and both kinds of block occur.
TEST(LabShadingPacket, BlocksThatSeeOnlyTheBackgroundEqualPackets) {
    const Scene scene = makeTriangleSoup(5000, 0.1f, 31);
    const Bvh bvh = buildBvh(scene);
    RenderSettings settings;
    settings.width = 128;
    settings.height = 96;
    settings.light.position = {0.5f, 2.0f, -1.5f};
    settings.camera.position = {0.4f, 0.3f, -7.0f}; // the soup fills the middle of the picture
    const PrimaryRays primary(settings.camera, settings.width, settings.height);
    int background = 0, other = 0;
    for (int y0 = 0; y0 < settings.height; y0 += kPacketSize) {
        for (int x0 = 0; x0 < settings.width; x0 += kPacketSize) {
            for (const float inset : {0.5f, 0.0f}) { // sample 0 at pixel centres, later anywhere
                RayPacket packets[kPacketSize];
                for (int r = 0; r < kPacketSize; ++r) {
                    for (int i = 0; i < kPacketSize; ++i) {
                        const float dx = inset == 0.5f ? 0.5f : (i % 3 == 0 ? 0.0f : 0.99f);
                        packets[r].set(i, primary.through(static_cast<float>(x0 + i) + dx,
                                                          static_cast<float>(y0 + r) + dx));
                    }
                }
                const ImageRect rect{static_cast<float>(x0) + inset, static_cast<float>(y0) + inset,
                                     static_cast<float>(x0 + kPacketSize) - inset,
                                     static_cast<float>(y0 + kPacketSize) - inset};
                (imageRectMissesScene(bvh, primary, rect) ? background : other) += 1;
                RadiancePacket block[kPacketSize], single[kPacketSize];
                RayCounts blockCounts, singleCounts;
                shadeLabBlock(scene, bvh, settings, primary, rect, packets, kPacketSize, block,
                              blockCounts, BlockTracing::Packets);
                for (int r = 0; r < kPacketSize; ++r) {
                    shadeLab8(scene, bvh, settings, packets[r], single[r], singleCounts);
                    ASSERT_EQ(std::memcmp(&block[r], &single[r], sizeof(RadiancePacket)), 0)
                        << "block " << x0 << ", " << y0 << " row " << r;
                }
                ASSERT_EQ(blockCounts.primary, singleCounts.primary);
                ASSERT_EQ(blockCounts.shadow, singleCounts.shadow);
            }
        }
    }
    if (bvhSimdSupported()) {
        EXPECT_GT(background, 20);
    }
    EXPECT_GT(other, 20);
}

// The renderer's rule: frustums for scenes of up to 4,096 leaf triangles where the CPU has
// AVX2, packets for larger ones.
TEST(LabShadingPacket, TracingForTheScene) {
    const BlockTracing small = bvhSimdSupported() ? BlockTracing::Frustums : BlockTracing::Packets;
    const Bvh box = buildBvh(makeCornellBox());
    EXPECT_EQ(tracingFor(box), small);
    const Bvh below = buildBvh(makeTriangleSoup(4000, 0.1f, 31));
    ASSERT_LE(below.leafReferences, 4096u);
    EXPECT_EQ(tracingFor(below), small);
    const Bvh above = buildBvh(makeTriangleSoup(4200, 0.1f, 31));
    ASSERT_GT(above.leafReferences, 4096u);
    EXPECT_EQ(tracingFor(above), BlockTracing::Packets);
}

// tilePixel lays a block's 8 packets out as four 4 x 4 tiles: every pixel of the 8 x 8 block
// once, each packet a 4 x 2 rectangle (lanes 0-3 one row, 4-7 the next), packets 2t and 2t + 1
// the upper and lower halves of one 4 x 4 square.
TEST(LabShadingPacket, TilePixelsCoverTheBlockInFourByFourTiles) {
    int seen[kPacketSize][kPacketSize] = {};
    for (int p = 0; p < kPacketSize; ++p) {
        const BlockPixel corner = tilePixel(p, 0);
        const BlockPixel tileCorner = tilePixel(p & ~1, 0);
        EXPECT_EQ(corner.x % 4, 0) << p;
        EXPECT_EQ(corner.y % 2, 0) << p;
        EXPECT_EQ(corner.x, tileCorner.x) << p;
        EXPECT_EQ(corner.y, tileCorner.y + (p % 2) * 2) << p;
        EXPECT_EQ(tileCorner.y % 4, 0) << p;
        for (int i = 0; i < kPacketSize; ++i) {
            const BlockPixel pixel = tilePixel(p, i);
            ASSERT_GE(pixel.x, 0);
            ASSERT_LT(pixel.x, kPacketSize);
            ASSERT_GE(pixel.y, 0);
            ASSERT_LT(pixel.y, kPacketSize);
            EXPECT_EQ(pixel.x, corner.x + i % 4) << p << " " << i;
            EXPECT_EQ(pixel.y, corner.y + i / 4) << p << " " << i;
            ++seen[pixel.y][pixel.x];
        }
    }
    for (int y = 0; y < kPacketSize; ++y) {
        for (int x = 0; x < kPacketSize; ++x) {
            EXPECT_EQ(seen[y][x], 1) << x << ", " << y;
        }
    }
}

// Full blocks of a scene traced packet by packet (shadeLabBlock regroups them as 4 x 4 tiles of
// 16 rays) against shadeLab8 row by row: the same radiance bit for bit in each row's lanes, and
// the same counts. Each row of blocks carries one TileCarry, as a tile of the renderer's does.
// Adds to `eightWalkBlocks`, when given, the blocks whose camera rays took eight walks
// (CameraWalks; never where the CPU has AVX-512).
void expectFullBlocksEqualPackets(const Scene& scene, const RenderSettings& settings,
                                  int* eightWalkBlocks = nullptr) {
    const Bvh bvh = buildBvh(scene);
    ASSERT_EQ(tracingFor(bvh), BlockTracing::Packets);
    const PrimaryRays primary(settings.camera, settings.width, settings.height);
    int lit = 0, shadowed = 0;
    for (int y0 = 0; y0 + kPacketSize <= settings.height; y0 += kPacketSize) {
        TileCarry carry;
        for (int x0 = 0; x0 + kPacketSize <= settings.width; x0 += kPacketSize) {
            RayPacket packets[kPacketSize];
            for (int r = 0; r < kPacketSize; ++r) {
                for (int i = 0; i < kPacketSize; ++i) {
                    packets[r].set(i, primary.through(static_cast<float>(x0 + i) + 0.5f,
                                                      static_cast<float>(y0 + r) + 0.5f));
                }
            }
            RadiancePacket block[kPacketSize], rows[kPacketSize];
            RayCounts blockCounts, rowCounts;
            if (eightWalkBlocks != nullptr && !bvhPacket16Supported() &&
                carry.cameraWalks.eightWalks()) {
                ++*eightWalkBlocks;
            }
            shadeLabBlock(scene, bvh, settings, packets, kPacketSize, block, blockCounts,
                          BlockTracing::ForScene, &carry);
            for (int r = 0; r < kPacketSize; ++r) {
                shadeLab8(scene, bvh, settings, packets[r], rows[r], rowCounts);
                ASSERT_EQ(std::memcmp(&block[r], &rows[r], sizeof(RadiancePacket)), 0)
                    << "block " << x0 << ", " << y0 << " row " << r;
                for (int i = 0; i < kPacketSize; ++i) {
                    lit += block[r].value[0][i] > 0.0f ? 1 : 0;
                }
            }
            ASSERT_EQ(blockCounts.primary, rowCounts.primary);
            ASSERT_EQ(blockCounts.shadow, rowCounts.shadow);
            shadowed += static_cast<int>(blockCounts.shadow);
        }
    }
    EXPECT_GT(lit, settings.width * settings.height / 8);
    if (settings.shadows) {
        EXPECT_GT(shadowed, settings.width * settings.height / 16);
    }
}

TEST(LabShadingPacket, FullBlocksInTilesEqualPackets) {
    RenderSettings settings;
    settings.width = 96;
    settings.height = 72;
    settings.light.position = {0.5f, 2.0f, -1.5f};
    expectFullBlocksEqualPackets(makeTriangleSoup(5000, 0.1f, 31), settings);
    settings.shadowEpsilon = 0.0f;
    expectFullBlocksEqualPackets(makeClosedSphere(48, 96, 0.8f, 0.01f, 5), settings);
    settings.shadows = false;
    expectFullBlocksEqualPackets(makeTriangleSoup(5000, 0.1f, 32), settings);
}

// A mesh whose triangles are a fraction of a pixel (a height field of 2 x 240^2 triangles seen
// whole): where the CPU has AVX2 alone, most of its blocks' camera rays take eight walks
// (CameraWalks), with the same radiance.
TEST(LabShadingPacket, FullBlocksOfSmallTrianglesInEightWalksEqualPackets) {
    RenderSettings settings;
    settings.width = 96;
    settings.height = 96;
    settings.camera.position = {0.0f, 0.0f, -2.6f};
    settings.light.position = {0.5f, 0.5f, -1.5f};
    int eightWalkBlocks = 0;
    expectFullBlocksEqualPackets(makeHeightField(240, 9), settings, &eightWalkBlocks);
    if (bvhPacket16Supported()) {
        EXPECT_EQ(eightWalkBlocks, 0);
    } else {
        EXPECT_GT(eightWalkBlocks, 12 * 12 / 2);
    }
}

} // namespace
} // namespace raylab::accel_test
