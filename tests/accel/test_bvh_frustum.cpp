// Frustum culling (bvh_frustum.h): for blocks of 8 x 8 camera rays and their shadow rays, the
// candidate triangles give every lane closestHit8's and anyHit8's answer bit for bit, and the
// frustum is refused where its contract does not hold.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/bvh/bvh_frustum.h"
#include "core/bvh/bvh_packet.h"
#include "core/bvh/traverse/bvh_packet16_traverse.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/render_settings.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <vector>

namespace raylab::accel_test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Block {
    RayPacket packets[kPacketSize];
    int count = 0;
};

// The camera rays of pixels [x0, x0 + 8) x [y0, y0 + 8) (clipped to the image), through random
// points of each pixel, its corners included.
Block cameraBlock(const PrimaryRays& primary, int width, int height, int x0, int y0,
                  std::mt19937& random) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, 5);
    Block block;
    block.count = std::min(kPacketSize, height - y0);
    for (int r = 0; r < block.count; ++r) {
        RayPacket& packet = block.packets[r];
        for (int i = 0; i < kPacketSize && x0 + i < width; ++i) {
            float dx = unit(random), dy = unit(random);
            const int corner = pick(random); // pixel corners, where the block's planes pass
            if (corner == 0) {
                dx = 0.0f;
                dy = 0.0f;
            } else if (corner == 1) {
                dx = std::nextafter(1.0f, 0.0f);
                dy = std::nextafter(1.0f, 0.0f);
            }
            packet.set(i, primary.through(static_cast<float>(x0 + i) + dx,
                                          static_cast<float>(y0 + r) + dy));
        }
    }
    return block;
}

// Shadow rays from the closest hits of a block towards `light`, as the lab's shading makes them.
Block shadowBlock(const Bvh& bvh, const Block& camera, const glm::vec3& light, float epsilon) {
    Block shadows;
    shadows.count = camera.count;
    for (int r = 0; r < camera.count; ++r) {
        HitPacket hits;
        closestHit8(bvh, camera.packets[r], hits);
        for (int i = 0; i < kPacketSize; ++i) {
            if (!hits.hit(i).found()) {
                continue;
            }
            const Ray ray = camera.packets[r].ray(i);
            const glm::vec3 point = ray.origin + hits.t[i] * ray.direction;
            const glm::vec3 toLight = light - point;
            const float distance = std::sqrt(glm::dot(toLight, toLight));
            if (distance > 0.0f) {
                shadows.packets[r].set(i,
                                       Ray{point, toLight / distance, epsilon, distance - epsilon});
            }
        }
    }
    return shadows;
}

struct Tally {
    int blocks = 0;         // blocks with at least one ray
    int withCandidates = 0; // blocks traced from their candidates
    int hits = 0;
    int pairsOf16 = 0;    // pairs of rows traced as 16 lanes (closestHitCandidates16 etc.)
    int pairsRefused = 0; // pairs those calls gave back (their lanes' permutations differ)
};

// A HitPacket whose every lane holds a hit no call makes: a lane left unwritten shows.
HitPacket garbageHits() {
    HitPacket hits;
    for (int i = 0; i < kPacketSize; ++i) {
        hits.set(i, Hit{-7.0f, 0.25f, 0.5f, 0xdeadu});
    }
    return hits;
}

bool hasRays(const Block& block) {
    for (int r = 0; r < block.count; ++r) {
        if (block.packets[r].lanes != 0) {
            return true;
        }
    }
    return false;
}

// Leaves share triangle blocks (bvh_collapse.cpp): a lane reached through two leaves is still
// one candidate.
void expectDistinct(const FrustumCandidates& candidates) {
    std::vector<uint64_t> keys;
    for (int i = 0; i < candidates.count; ++i) {
        keys.push_back(uint64_t{candidates.block[i]} << 8 | candidates.lane[i]);
    }
    std::sort(keys.begin(), keys.end());
    EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end())
        << "a block's lane collected twice among " << candidates.count << " candidates";
}

// Every lane of the block: closestHitCandidates == closestHit8 when the frustum fits. The
// frustum is the one fitted to the rays, or with `camera`, the one of the image rectangle `rect`
// the rays were made from (frustumOfImageRect).
void expectCameraBlockExact(const Bvh& bvh, const Block& block, Tally& tally,
                            const PrimaryRays* camera = nullptr, const ImageRect& rect = {}) {
    if (!hasRays(block)) {
        return;
    }
    ++tally.blocks;
    RayFrustum frustum;
    FrustumCandidates candidates;
    const bool framed = camera ? frustumOfImageRect(bvh, *camera, rect, frustum)
                               : frustumOfRays(bvh, block.packets, block.count, frustum);
    if (!framed || !frustumCandidates(bvh, frustum, candidates)) {
        return;
    }
    ++tally.withCandidates;
    expectDistinct(candidates);
    for (int r = 0; r < block.count; ++r) {
        HitPacket expected, got;
        closestHit8(bvh, block.packets[r], expected);
        closestHitCandidates(bvh, candidates, block.packets[r], got);
        for (int i = 0; i < kPacketSize; ++i) {
            ASSERT_TRUE(sameHit(got.hit(i), expected.hit(i)))
                << "row " << r << " lane " << i << ": candidates t=" << got.t[i]
                << " tri=" << got.triangle[i] << ", packet t=" << expected.t[i]
                << " tri=" << expected.triangle[i] << " (" << candidates.count << " candidates)";
            tally.hits += expected.hit(i).found() ? 1 : 0;
        }
    }
    if (!bvhPacket16Supported()) {
        return;
    }
    // Rows two by two on 16 lanes: the same answers where the call takes them.
    for (int r = 0; r + 1 < block.count; r += 2) {
        HitPacket got[2] = {garbageHits(), garbageHits()};
        if (!closestHitCandidates16(bvh, candidates, block.packets[r], block.packets[r + 1], got[0],
                                    got[1])) {
            ++tally.pairsRefused;
            continue;
        }
        ++tally.pairsOf16;
        for (int h = 0; h < 2; ++h) {
            HitPacket expected;
            closestHit8(bvh, block.packets[r + h], expected);
            for (int i = 0; i < kPacketSize; ++i) {
                ASSERT_TRUE(sameHit(got[h].hit(i), expected.hit(i)))
                    << "row " << r + h << " lane " << i << " of a 16-lane pair: t=" << got[h].t[i]
                    << " tri=" << got[h].triangle[i] << ", packet t=" << expected.t[i]
                    << " tri=" << expected.triangle[i];
            }
        }
    }
}

void expectShadowBlockExact(const Bvh& bvh, const Block& block, const glm::vec3& light,
                            Tally& tally) {
    if (!hasRays(block)) {
        return;
    }
    ++tally.blocks;
    RayFrustum frustum;
    FrustumCandidates candidates;
    if (!frustumOfSegments(bvh, block.packets, block.count, light, frustum) ||
        !frustumCandidates(bvh, frustum, candidates)) {
        return;
    }
    ++tally.withCandidates;
    expectDistinct(candidates);
    for (int r = 0; r < block.count; ++r) {
        const unsigned expected = anyHit8(bvh, block.packets[r]);
        const unsigned got = anyHitCandidates(bvh, candidates, block.packets[r]);
        ASSERT_EQ(got, expected) << "row " << r << " (" << candidates.count << " candidates)";
        tally.hits += __builtin_popcount(expected);
    }
    if (!bvhPacket16Supported()) {
        return;
    }
    for (int r = 0; r + 1 < block.count; r += 2) {
        unsigned got = 0xdeadbeefu;
        if (!anyHitCandidates16(bvh, candidates, block.packets[r], block.packets[r + 1], got)) {
            ++tally.pairsRefused;
            continue;
        }
        ++tally.pairsOf16;
        const unsigned expected =
            anyHit8(bvh, block.packets[r]) | anyHit8(bvh, block.packets[r + 1]) << kPacketSize;
        ASSERT_EQ(got, expected) << "rows " << r << " and " << r + 1 << " on 16 lanes";
    }
}

// Every block of a width x height image from `camera`, its camera rays through both kinds of
// frustum (rectTally counts the image rectangle's), and the shadow rays towards `light`.
void expectImageExact(const Scene& scene, const Camera& camera, const glm::vec3& light,
                      float epsilon, Tally& cameraTally, Tally& rectTally, Tally& shadowTally,
                      uint32_t seed) {
    const Bvh bvh = buildBvh(scene);
    if (bvh.wideNodes.empty()) {
        GTEST_SKIP() << "no AVX2: the frustum path is never taken";
    }
    const int width = 100, height = 60; // partial blocks on the right and at the bottom
    const PrimaryRays primary(camera, width, height);
    std::mt19937 random(seed);
    for (int y0 = 0; y0 < height; y0 += kPacketSize) {
        for (int x0 = 0; x0 < width; x0 += kPacketSize) {
            const Block block = cameraBlock(primary, width, height, x0, y0, random);
            expectCameraBlockExact(bvh, block, cameraTally);
            const ImageRect rect{static_cast<float>(x0), static_cast<float>(y0),
                                 static_cast<float>(std::min(width, x0 + kPacketSize)),
                                 static_cast<float>(std::min(height, y0 + kPacketSize))};
            expectCameraBlockExact(bvh, block, rectTally, &primary, rect);
            expectShadowBlockExact(bvh, shadowBlock(bvh, block, light, epsilon), light,
                                   shadowTally);
            if (testing::Test::HasFatalFailure()) {
                return;
            }
        }
    }
}

TEST(BvhFrustum, CornellBoxBlocksAreExactAndCulled) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    const RenderSettings lab;
    for (float epsilon : {1e-3f, 0.0f}) {
        Tally cameraTally, rectTally, shadowTally;
        expectImageExact(makeCornellBox(), lab.camera, lab.light.position, epsilon, cameraTally,
                         rectTally, shadowTally, 7);
        ASSERT_FALSE(HasFatalFailure());
        // The box's 30 large triangles: every block's frustum holds few of them.
        EXPECT_EQ(cameraTally.withCandidates, cameraTally.blocks);
        EXPECT_EQ(rectTally.withCandidates, rectTally.blocks);
        EXPECT_EQ(rectTally.hits, cameraTally.hits);
        EXPECT_GT(shadowTally.withCandidates, shadowTally.blocks * 3 / 4)
            << shadowTally.withCandidates << " of " << shadowTally.blocks;
        EXPECT_GT(cameraTally.hits, 3000);
        EXPECT_GT(shadowTally.hits, 100); // the blocks cast shadows
        if (bvhPacket16Supported()) {
            // Of at most 4 pairs a block: the camera rays' all (z their largest direction
            // component everywhere in the lab's field of view), the shadow rays' most (rays
            // towards the light from walls facing different ways differ in permutation).
            EXPECT_EQ(cameraTally.pairsRefused + rectTally.pairsRefused, 0);
            EXPECT_GT(rectTally.pairsOf16, rectTally.withCandidates * 3);
            EXPECT_GT(shadowTally.pairsOf16, shadowTally.withCandidates * 2);
        }
    }
}

TEST(BvhFrustum, RandomCamerasOnSoupsHeightFieldAndSphere) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    const Scene scenes[] = {makeTriangleSoup(300, 0.6f, 3), makeTriangleSoup(3000, 0.15f, 4),
                            makeHeightField(12, 5), makeClosedSphere(8, 12, 0.8f, 0.05f, 6)};
    std::mt19937 random(11);
    std::uniform_real_distribution<float> position(-2.5f, 2.5f);
    // Narrow to nearly flat fields of view: the rectangle's planes come from the focal length.
    const float fovs[] = {50.0f, 100.0f, 0.5f, 170.0f};
    Tally cameraTally, rectTally, shadowTally;
    for (const Scene& scene : scenes) {
        for (int view = 0; view < 4; ++view) {
            Camera camera;
            camera.position = {position(random), position(random), position(random)};
            lookAt(camera, {0.1f * position(random), 0.1f * position(random), 0.0f});
            camera.verticalFovDegrees = fovs[view];
            const glm::vec3 light{position(random), 2.0f, position(random)};
            expectImageExact(scene, camera, light, 1e-3f, cameraTally, rectTally, shadowTally,
                             static_cast<uint32_t>(view));
            ASSERT_FALSE(HasFatalFailure());
        }
    }
    EXPECT_GT(cameraTally.withCandidates, cameraTally.blocks / 4);
    EXPECT_GT(rectTally.withCandidates, rectTally.blocks / 4);
    EXPECT_GT(rectTally.hits, 10000);
    EXPECT_GT(shadowTally.withCandidates, 0);
    EXPECT_GT(cameraTally.hits, 10000);
    EXPECT_GT(shadowTally.hits, 1000);
    if (bvhPacket16Supported()) {
        // Most pairs share one permutation; wide fields of view also give pairs that do not.
        EXPECT_GT(cameraTally.pairsOf16 + rectTally.pairsOf16, 1000);
        EXPECT_GT(shadowTally.pairsOf16, 100);
        EXPECT_GT(cameraTally.pairsRefused + rectTally.pairsRefused + shadowTally.pairsRefused, 0);
    } else {
        GTEST_LOG_(INFO) << "this CPU has no AVX-512F: the 16-lane candidate tests are not run";
    }
}

// imageRectMissesScene: a block's rectangle reported to miss holds no ray that hits (brute force
// at its corners, edges and random points), over random cameras and fields of view; and it does
// report the blocks that see only the background, so that the renderer and the bench skip them.
TEST(BvhFrustum, ImageRectMissesSceneOnlyWhereEveryRayMisses) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    const Scene scenes[] = {makeTriangleSoup(300, 0.6f, 3), makeHeightField(12, 5),
                            makeClosedSphere(8, 12, 0.8f, 0.05f, 6)};
    std::mt19937 random(21);
    std::uniform_real_distribution<float> position(-4.0f, 4.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float fovs[] = {50.0f, 100.0f, 0.5f, 170.0f, 20.0f};
    constexpr int kWidth = 96, kHeight = 64;
    int missing = 0, notMissing = 0, raysChecked = 0;
    for (const Scene& scene : scenes) {
        const Bvh bvh = buildBvh(scene);
        for (const float fov : fovs) {
            Camera camera;
            camera.position = {position(random), position(random), position(random)};
            lookAt(camera, {0.3f * position(random), 0.3f * position(random), 0.0f});
            camera.verticalFovDegrees = fov;
            const PrimaryRays primary(camera, kWidth, kHeight);
            for (int y0 = 0; y0 < kHeight; y0 += kPacketSize) {
                for (int x0 = 0; x0 < kWidth; x0 += kPacketSize) {
                    // The renderer's rectangles: pixel centres (sample 0) and whole pixels.
                    for (const float inset : {0.5f, 0.0f}) {
                        const float x1 = static_cast<float>(x0 + kPacketSize) - inset;
                        const float y1 = static_cast<float>(y0 + kPacketSize) - inset;
                        const ImageRect rect{static_cast<float>(x0) + inset,
                                             static_cast<float>(y0) + inset, x1, y1};
                        if (!imageRectMissesScene(bvh, primary, rect)) {
                            ++notMissing;
                            continue;
                        }
                        ++missing;
                        for (int k = 0; k < 40; ++k) {
                            // Corners first, then points on the edges and inside.
                            float u = unit(random), v = unit(random);
                            if (k < 4) {
                                u = static_cast<float>(k & 1);
                                v = static_cast<float>(k >> 1);
                            } else if (k < 12) {
                                (k & 1 ? u : v) = static_cast<float>((k >> 1) & 1);
                            }
                            const float px = rect.x0 + u * (rect.x1 - rect.x0);
                            const float py = rect.y0 + v * (rect.y1 - rect.y0);
                            ASSERT_FALSE(
                                closestHitBruteForce(scene, primary.through(px, py)).found())
                                << "a ray through (" << px << ", " << py << ") hits, fov " << fov;
                            ++raysChecked;
                        }
                    }
                }
            }
        }
    }
    EXPECT_GT(missing, 200);
    EXPECT_GT(notMissing, 200);
    EXPECT_GT(raysChecked, 8000);
}

// imageRectMissesScene answers as the pyramid frustumOfImageRect makes, tested against the root's
// children plane by plane with each box's corner farthest along the plane's normal (the reference
// here, in the same float operations), on rectangles of every size and place, whole pixels or
// parts of them.
TEST(BvhFrustum, ImageRectMissesSceneIsTheRectanglesPyramidAgainstTheRoot) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    const Scene scenes[] = {makeTriangleSoup(300, 0.6f, 3), makeHeightField(12, 5),
                            makeCornellBox()};
    std::mt19937 random(33);
    std::uniform_real_distribution<float> position(-4.0f, 4.0f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    constexpr int kWidth = 64, kHeight = 48;
    int missing = 0, notMissing = 0;
    for (const Scene& scene : scenes) {
        const Bvh bvh = buildBvh(scene);
        ASSERT_FALSE(bvh.wideNodes.empty());
        const BvhWideNode& root = bvh.wideNodes[0];
        for (int view = 0; view < 40; ++view) {
            Camera camera;
            camera.position = {position(random), position(random), position(random)};
            lookAt(camera, {0.3f * position(random), 0.3f * position(random), 0.0f});
            camera.verticalFovDegrees = 5.0f + 160.0f * unit(random);
            const PrimaryRays primary(camera, kWidth, kHeight);
            // Where the children's corners are seen: rectangles with an edge at one of them, or
            // a hair's breadth to either side, are where the planes' tolerance decides.
            std::vector<glm::vec2> corners;
            for (int c = 0; c < kWideLanes; ++c) {
                for (int k = 0; k < 8 && root.child[c] != kWideEmpty; ++k) {
                    const glm::vec3 corner{(k & 1 ? root.upper : root.lower)[0][c],
                                           (k & 2 ? root.upper : root.lower)[1][c],
                                           (k & 4 ? root.upper : root.lower)[2][c]};
                    const glm::vec3 seen = primary.cameraFrom(corner);
                    if (seen.z > 0.0f) {
                        corners.push_back(primary.imageFrom(seen));
                    }
                }
            }
            const float hair[] = {-1e-2f, -1e-3f, -1e-4f, 0.0f, 1e-4f, 1e-3f, 1e-2f};
            std::uniform_int_distribution<int> pickHair(0, 6);
            for (int r = 0; r < 50 + 4 * static_cast<int>(corners.size()); ++r) {
                float x[2] = {kWidth * unit(random), kWidth * unit(random)};
                float y[2] = {kHeight * unit(random), kHeight * unit(random)};
                if (r % 5 == 0) { // whole pixels
                    for (float* c : {&x[0], &x[1], &y[0], &y[1]}) {
                        *c = std::floor(*c);
                    }
                }
                if (r >= 50) { // an edge through a corner: the left, right, top or bottom one
                    const glm::vec2 p = corners[static_cast<std::size_t>(r - 50) / 4];
                    const float h = hair[pickHair(random)];
                    ((r & 2) == 0 ? x : y)[r & 1] = ((r & 2) == 0 ? p.x : p.y) + h;
                }
                const ImageRect rect{std::min(x[0], x[1]), std::min(y[0], y[1]),
                                     std::max(x[0], x[1]), std::max(y[0], y[1])};
                RayFrustum frustum;
                ASSERT_TRUE(frustumOfImageRect(bvh, primary, rect, frustum));
                bool rootMissed = true;
                for (int c = 0; c < kWideLanes; ++c) {
                    if (root.child[c] == kWideEmpty) {
                        continue;
                    }
                    bool inside = true;
                    for (int j = 0; j < frustum.planeCount; ++j) {
                        const glm::vec3& n = frustum.normal[j];
                        float d[3];
                        for (int a = 0; a < 3; ++a) {
                            const float bound = n[a] >= 0.0f ? root.upper[a][c] : root.lower[a][c];
                            d[a] = (bound - frustum.apex[a]) * n[a];
                        }
                        const float distance =
                            ((d[0] + d[1]) + d[2]) + (frustum.offset[j] + frustum.tolerance);
                        inside = inside && !(distance < 0.0f);
                    }
                    rootMissed = rootMissed && !inside;
                }
                const bool missed = imageRectMissesScene(bvh, primary, rect);
                ASSERT_EQ(missed, rootMissed) << "rectangle (" << rect.x0 << ", " << rect.y0
                                              << ") - (" << rect.x1 << ", " << rect.y1 << ")";
                ++(missed ? missing : notMissing);
            }
        }
    }
    EXPECT_GT(missing, 500);
    EXPECT_GT(notMissing, 500);
}

TEST(BvhFrustum, FarFromTheOriginStaysExact) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    // The box moved 3000 units away: coordinates keep fewer bits below the unit.
    Scene scene = makeCornellBox();
    const glm::vec3 offset{3000.0f, -2000.0f, 1000.0f};
    for (Triangle& t : scene.triangles) {
        t.v0 += offset;
        t.v1 += offset;
        t.v2 += offset;
    }
    const RenderSettings lab;
    Camera camera = lab.camera;
    camera.position += offset;
    Tally cameraTally, rectTally, shadowTally;
    expectImageExact(scene, camera, lab.light.position + offset, 1e-3f, cameraTally, rectTally,
                     shadowTally, 9);
    ASSERT_FALSE(HasFatalFailure());
    EXPECT_EQ(cameraTally.withCandidates, cameraTally.blocks);
    EXPECT_EQ(rectTally.withCandidates, rectTally.blocks);
    EXPECT_GT(cameraTally.hits, 3000);
}

// The tolerance scales with the largest |coordinate| of the BVH's node boxes (the build records
// the vertices' largest, Bvh::largestCoordinate; the boxes reach boxPad further) or of the apex,
// whichever is larger; an invalid triangle's far vertex counts for neither.
TEST(BvhFrustum, ToleranceScalesWithTheNodeBoxesAndTheApex) {
    Scene scene = makeTriangleSoup(200, 0.1f, 5);
    for (Triangle& t : scene.triangles) {
        t.v0 = t.v0 * 40.0f - glm::vec3(7.0f);
        t.v1 = t.v1 * 40.0f - glm::vec3(7.0f);
        t.v2 = t.v2 * 40.0f - glm::vec3(7.0f);
    }
    Triangle degenerate;
    degenerate.v0 = degenerate.v1 = degenerate.v2 = glm::vec3(0.0f, 1e6f, 0.0f);
    scene.triangles.push_back(degenerate);
    float largest = 0.0f;
    for (std::size_t i = 0; i + 1 < scene.triangles.size(); ++i) {
        for (const glm::vec3& v :
             {scene.triangles[i].v0, scene.triangles[i].v1, scene.triangles[i].v2}) {
            largest = std::max({largest, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
        }
    }
    for (const bool simd : {true, false}) {
        BvhBuildOptions options;
        options.simd = simd;
        options.keepBinaryNodes = true;
        const Bvh bvh = buildBvh(scene, options);
        ASSERT_EQ(bvh.skippedTriangles, 1u);
        EXPECT_EQ(bvh.largestCoordinate, largest);
        const Aabb root = bvh.bounds();
        const float rootLargest =
            std::max({std::fabs(root.lower.x), std::fabs(root.lower.y), std::fabs(root.lower.z),
                      std::fabs(root.upper.x), std::fabs(root.upper.y), std::fabs(root.upper.z)});
        // Within a few ulps of the root box's own largest coordinate.
        EXPECT_NEAR(frustumTolerance(bvh, glm::vec3(0.0f)), 4e-5f * rootLargest,
                    4e-5f * rootLargest * 1e-6f);
        EXPECT_GE(frustumTolerance(bvh, glm::vec3(0.0f)), 4e-5f * rootLargest);
        EXPECT_FLOAT_EQ(frustumTolerance(bvh, glm::vec3(0.0f, 0.0f, -500.0f)), 4e-5f * 500.0f);
    }
    EXPECT_EQ(buildBvh(Scene{}).largestCoordinate, 0.0f);
}

// A triangle with an edge along the block's outermost rays (its first column) is a candidate and
// gives those rays closestHit8's answers; one wholly beside the block is culled.
TEST(BvhFrustum, TriangleAlongTheBlockEdgeIsKeptOneBesideItCulled) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    const Camera camera;
    const PrimaryRays primary(camera, 64, 64);
    Block block;
    block.count = kPacketSize;
    for (int r = 0; r < kPacketSize; ++r) {
        for (int i = 0; i < kPacketSize; ++i) {
            block.packets[r].set(
                i, primary.through(static_cast<float>(16 + i), static_cast<float>(16 + r)));
        }
    }
    // Through the left column's top and bottom rays, and away to the left of the block.
    const Ray top = block.packets[0].ray(0);
    const Ray bottom = block.packets[kPacketSize - 1].ray(0);
    Scene scene;
    scene.materials.push_back(Material{});
    const glm::vec3 a = top.origin + 4.0f * top.direction;
    const glm::vec3 b = bottom.origin + 4.0f * bottom.direction;
    scene.triangles.push_back(Triangle{a, b, a + glm::vec3(3.0f, 0.0f, 0.0f), 0});
    // A second triangle wholly outside, to be culled.
    scene.triangles.push_back(Triangle{a + glm::vec3(5.0f, 0, 0), b + glm::vec3(5.0f, 0, 0),
                                       a + glm::vec3(6.0f, 0, 0), 0});
    const Bvh bvh = buildBvh(scene);
    RayFrustum frustum;
    FrustumCandidates candidates;
    // The rays are through the pixels' corners: the rectangle's left edge holds the left column.
    const ImageRect rect{16.0f, 16.0f, 16.0f + kPacketSize - 1, 16.0f + kPacketSize - 1};
    ASSERT_TRUE(frustumOfImageRect(bvh, primary, rect, frustum));
    ASSERT_TRUE(frustumCandidates(bvh, frustum, candidates));
    ASSERT_EQ(candidates.count, 1);
    ASSERT_TRUE(frustumOfRays(bvh, block.packets, block.count, frustum));
    ASSERT_TRUE(frustumCandidates(bvh, frustum, candidates));
    ASSERT_EQ(candidates.count, 1);
    int hits = 0;
    for (int r = 0; r < kPacketSize; ++r) {
        HitPacket expected, got;
        closestHit8(bvh, block.packets[r], expected);
        closestHitCandidates(bvh, candidates, block.packets[r], got);
        for (int i = 0; i < kPacketSize; ++i) {
            EXPECT_TRUE(sameHit(got.hit(i), expected.hit(i))) << r << ", " << i;
            hits += expected.hit(i).found() ? 1 : 0;
        }
    }
    EXPECT_GT(hits, 0);
}

TEST(BvhFrustum, RefusedWhereTheContractDoesNotHold) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    const Bvh bvh = buildBvh(makeCornellBox());
    const RenderSettings lab;
    const PrimaryRays primary(lab.camera, 64, 64);
    auto fresh = [&] {
        Block block;
        block.count = 2;
        for (int r = 0; r < 2; ++r) {
            for (int i = 0; i < kPacketSize; ++i) {
                block.packets[r].set(
                    i, primary.through(static_cast<float>(i) + 0.5f, static_cast<float>(r) + 0.5f));
            }
        }
        return block;
    };
    RayFrustum frustum;
    Block block = fresh();
    ASSERT_TRUE(frustumOfRays(bvh, block.packets, block.count, frustum));
    EXPECT_EQ(frustum.planeCount, 4);
    EXPECT_GT(frustum.tolerance, 0.0f);

    block.packets[1].origin[1][3] += 1e-3f; // another origin
    EXPECT_FALSE(frustumOfRays(bvh, block.packets, block.count, frustum));
    block = fresh();
    block.packets[0].direction[2][5] = kNaN;
    EXPECT_FALSE(frustumOfRays(bvh, block.packets, block.count, frustum));
    block = fresh();
    // Opposite the first ray: no axis has both within 78 degrees.
    block.packets[1].set(7, Ray{lab.camera.position, -block.packets[0].ray(0).direction});
    EXPECT_FALSE(frustumOfRays(bvh, block.packets, block.count, frustum));
    block = fresh();
    block.packets[0].lanes = 0;
    block.packets[1].lanes = 0;
    EXPECT_FALSE(frustumOfRays(bvh, block.packets, block.count, frustum)); // no ray at all
    // A NaN lane outside the lane mask is never read.
    block = fresh();
    block.packets[0].direction[0][7] = kNaN;
    block.packets[0].lanes = 0x7f;
    EXPECT_TRUE(frustumOfRays(bvh, block.packets, block.count, frustum));

    // The image rectangle: refused when empty, not finite, or the camera is not finite.
    EXPECT_TRUE(frustumOfImageRect(bvh, primary, ImageRect{0, 0, 8, 2}, frustum));
    EXPECT_EQ(frustum.planeCount, 4);
    EXPECT_TRUE(frustumOfImageRect(bvh, primary, ImageRect{3, 1, 3, 1}, frustum)); // one point
    EXPECT_FALSE(frustumOfImageRect(bvh, primary, ImageRect{8, 0, 0, 2}, frustum));
    EXPECT_FALSE(frustumOfImageRect(bvh, primary, ImageRect{0, 0, kNaN, 2}, frustum));
    PrimaryRays broken = primary;
    broken.origin.y = kNaN;
    EXPECT_FALSE(frustumOfImageRect(bvh, broken, ImageRect{0, 0, 8, 2}, frustum));
    broken = primary;
    broken.forward.x = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(frustumOfImageRect(bvh, broken, ImageRect{0, 0, 8, 2}, frustum));

    block = fresh();
    EXPECT_TRUE(frustumOfSegments(bvh, block.packets, block.count, lab.light.position, frustum));
    EXPECT_EQ(frustum.planeCount, 5);
    block.packets[0].origin[0][2] = kNaN;
    EXPECT_FALSE(frustumOfSegments(bvh, block.packets, block.count, lab.light.position, frustum));
    // A segment end at the apex itself has no direction.
    block = fresh();
    EXPECT_FALSE(frustumOfSegments(bvh, block.packets, block.count, lab.camera.position, frustum));
}

TEST(BvhFrustum, TooManyTrianglesIsReported) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no AVX2";
    }
    // A dense soup seen whole: far more than kMaxFrustumCandidates in one wide frustum.
    const Bvh bvh = buildBvh(makeTriangleSoup(4000, 0.05f, 8));
    Camera camera;
    camera.position = {0.0f, 0.0f, -4.0f};
    camera.verticalFovDegrees = 90.0f;
    const PrimaryRays primary(camera, 2, 2);
    Block block;
    block.count = 2;
    for (int r = 0; r < 2; ++r) {
        for (int i = 0; i < 2; ++i) {
            block.packets[r].set(i, primary.through(static_cast<float>(i), static_cast<float>(r)));
            block.packets[r].set(
                i + 2, primary.through(static_cast<float>(i + 1), static_cast<float>(r + 1)));
        }
    }
    RayFrustum frustum;
    FrustumCandidates candidates;
    ASSERT_TRUE(frustumOfRays(bvh, block.packets, block.count, frustum));
    EXPECT_FALSE(frustumCandidates(bvh, frustum, candidates));
}

} // namespace
} // namespace raylab::accel_test
