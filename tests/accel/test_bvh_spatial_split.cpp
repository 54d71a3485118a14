// Spatial splits in the build (core/bvh_spatial_split.h): triangles cut by split planes sit in
// several leaves and must still give brute force's answers, bit for bit, on every path (scalar,
// SIMD, packets), within the reference budget, and the same tree for any thread count.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/bvh/build/bvh_build_object_split.h"
#include "core/bvh/build/bvh_build_subtree.h"
#include "core/bvh/build/bvh_spatial_split.h"
#include "core/bvh/bvh_packet.h"

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <random>

namespace raylab::accel_test {
namespace {

// A room-like scene: large quads (floor, walls, slabs at random heights) across the whole
// extent, among small triangles; object splits cannot separate the large ones.
Scene makeRoom(int smallCount, uint32_t seed) {
    Scene scene = makeTriangleSoup(smallCount, 0.05f, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < 40; ++i) {
        const float h = unit(rng);
        const int axis = i % 3;
        glm::vec3 p[4];
        for (int k = 0; k < 4; ++k) {
            const float s = (k == 1 || k == 2) ? 1.0f : -1.0f, t = k >= 2 ? 1.0f : -1.0f;
            p[k][axis] = h + 0.01f * unit(rng); // slightly tilted
            p[k][(axis + 1) % 3] = s;
            p[k][(axis + 2) % 3] = t;
        }
        scene.triangles.push_back({p[0], p[1], p[2], 0});
        scene.triangles.push_back({p[0], p[2], p[3], 0});
    }
    return scene;
}

BvhBuildOptions spatialOnly(float budget) {
    BvhBuildOptions options;
    options.presplitBudget = 0.0f;
    options.spatialSplitBudget = budget;
    return options;
}

// At spatial budget `none` the build makes no extra references; at `some` it makes some, and no
// more than the budget allows.
void expectSplitsOnlyFrom(const Scene& scene, float none, float some) {
    const std::size_t valid = scene.triangles.size();
    EXPECT_EQ(buildBvh(scene, spatialOnly(none)).leafReferences, valid) << "budget " << none;
    const Bvh bvh = buildBvh(scene, spatialOnly(some));
    EXPECT_GT(bvh.leafReferences, valid) << "budget " << some;
    EXPECT_LE(bvh.leafReferences, valid + static_cast<std::size_t>(static_cast<double>(some) *
                                                                   static_cast<double>(valid)))
        << "budget " << some;
}

TEST(BvhSpatialSplit, SplitsLargeTrianglesWithinTheBudget) {
    expectSplitsOnlyFrom(makeRoom(3000, 41), 0.0f, 0.3f);
}

// Where every triangle spans at most 1/16 of the scene on every axis (the room's small
// triangles alone, like a scanned mesh), neither spatial splits nor pre-splits are tried
// (bvh_build.cpp); the room's wide quads bring them back (above), and the answers are brute
// force's either way.
TEST(BvhSpatialSplit, NoneWhereEveryTriangleIsNarrowerThanASpatialBin) {
    BvhBuildOptions both;
    both.presplitBudget = 2.0f;
    both.spatialSplitBudget = 0.3f;
    for (const Scene& scene :
         {makeTriangleSoup(20000, 0.05f, 46), makeClosedSphere(90, 120, 1.0f, 0.02f, 47)}) {
        const Bvh bvh = buildBvh(scene, both);
        EXPECT_EQ(bvh.leafReferences, scene.triangles.size() - bvh.skippedTriangles);
        EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(4000, 48)), 100);
    }
    BvhBuildOptions presplitOnly = both;
    presplitOnly.spatialSplitBudget = 0.0f;
    const Scene room = makeRoom(3000, 49);
    EXPECT_GT(buildBvh(room, presplitOnly).leafReferences, room.triangles.size());
}

TEST(BvhSpatialSplit, MatchesBruteForceOnEveryPath) {
    const Scene scene = makeRoom(3000, 42);
    for (const float budget : {0.3f, 1.0f}) {
        const Bvh bvh = buildBvh(scene, spatialOnly(budget));
        EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(6000, 43)), 1000);
        expectMatchesBruteForce(scene, bvh, makeAxisAlignedRays(4000, 1.1f, 44));
        const std::vector<Ray> rays = makeRandomRays(4000, 45);
        for (std::size_t i = 0; i + kPacketSize <= rays.size(); i += kPacketSize) {
            Hit hits[kPacketSize];
            bool occluded[kPacketSize];
            closestHit8(bvh, &rays[i], kPacketSize, hits);
            anyHit8(bvh, &rays[i], kPacketSize, occluded);
            for (int k = 0; k < kPacketSize; ++k) {
                const Ray& ray = rays[i + static_cast<std::size_t>(k)];
                ASSERT_TRUE(sameHit(hits[k], closestHitBruteForce(scene, ray))) << i + k;
                ASSERT_EQ(occluded[k], anyHitBruteForce(scene, ray)) << i + k;
            }
        }
    }
}

// The room large enough that its top nodes choose their spatial splits from samples (more than
// 2,048 references): still brute force's answers.
TEST(BvhSpatialSplit, SampledSplitsMatchBruteForce) {
    const Scene scene = makeRoom(9000, 51);
    const Bvh bvh = buildBvh(scene, spatialOnly(0.3f));
    EXPECT_GT(bvh.leafReferences, scene.triangles.size());
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(1000, 52)), 200);
}

TEST(BvhSpatialSplit, WithPresplittingToo) {
    const Scene scene = makeRoom(2000, 46);
    BvhBuildOptions both;
    both.presplitBudget = 1.0f;
    both.spatialSplitBudget = 1.0f;
    const Bvh bvh = buildBvh(scene, both);
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(6000, 47)), 1000);
}

// Spatial bins along one axis: a reference across the node is cut at every plane of that axis
// it crosses, each bin taking the part of its box in the bin's slab; a reference inside one bin
// goes to it whole; nothing is binned along the other axes.
TEST(BvhSpatialSplit, BinsCutAReferenceAtEveryPlaneOfTheirAxis) {
    const Aabb bounds{{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.25f}};
    const PrimRecord across{{0.0f, 0.0f, 0.0f}, 0, {1.0f, 1.0f, 0.25f}, 0.0f};
    const PrimRecord inside{{0.3f, 0.3f, 0.1f}, 1, {0.31f, 0.31f, 0.2f}, 0.0f}; // bin 4 of x, y
    const float width = 1.0f / static_cast<float>(kSpatialBins);
    for (const int axis : {0, 1}) {
        SCOPED_TRACE(axis);
        SpatialBins bins;
        binSpatial(&across, &across + 1, bounds, axis, bins);
        EXPECT_EQ(bins.entering[0], 1u);
        EXPECT_EQ(bins.leaving[kSpatialBins - 1], 1u);
        uint32_t entering = 0, leaving = 0;
        for (int b = 0; b < kSpatialBins; ++b) {
            entering += bins.entering[b];
            leaving += bins.leaving[b];
            const Aabb part = bins.box[b].toAabb();
            ASSERT_FALSE(part.empty()) << b;
            EXPECT_FLOAT_EQ(part.lower[axis], static_cast<float>(b) * width) << b;
            EXPECT_FLOAT_EQ(part.upper[axis], static_cast<float>(b + 1) * width) << b;
            const int other = 1 - axis;
            EXPECT_EQ(part.lower[other], 0.0f) << b;
            EXPECT_EQ(part.upper[other], 1.0f) << b;
            EXPECT_EQ(part.lower.z, 0.0f) << b;
            EXPECT_EQ(part.upper.z, 0.25f) << b;
        }
        EXPECT_EQ(entering, 1u);
        EXPECT_EQ(leaving, 1u);

        SpatialBins one;
        binSpatial(&inside, &inside + 1, bounds, axis, one);
        for (int b = 0; b < kSpatialBins; ++b) {
            EXPECT_EQ(one.entering[b], b == 4 ? 1u : 0u) << b;
            EXPECT_EQ(one.leaving[b], b == 4 ? 1u : 0u) << b;
            EXPECT_EQ(one.box[b].toAabb().empty(), b != 4) << b;
        }
        const Aabb whole = one.box[4].toAabb();
        EXPECT_EQ(whole.lower, inside.lower);
        EXPECT_EQ(whole.upper, inside.upper);
    }
}

// A reference cut in two: each part keeps the reference's scene index in lane 3 of its lower
// corner and takes 0 in lane 3 of its upper corner (PrimRecord), whatever the clip left there
// (here the left part's clipped vertices' lanes 3, the fields after them, are all negative).
TEST(BvhSpatialSplit, CutPartsKeepTheirSceneIndexAndAZeroBesideTheirUpperCorner) {
    Scene scene;
    scene.materials.push_back({});
    scene.triangles.push_back({{5.0f, 5.0f, 5.0f}, {6.0f, 5.0f, 5.0f}, {5.0f, 6.0f, 5.0f}, 0});
    scene.triangles.push_back({{-1.0f, 0.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}, {-0.5f, 0.0f, 0.0f}, 0});
    const PrimRecord whole{{-1.0f, 0.0f, 0.0f}, 1, {-0.5f, 1.0f, 0.0f}, 0.0f};
    SpatialSplit split;
    split.axis = 0;
    split.position = -0.75f;
    PrimRecord left{}, right{};
    RecordBounds leftBounds, rightBounds;
    const SpatialSides sides = applySpatialSplit(scene, &whole, &whole + 1, split, 0.0f, &left,
                                                 &right, leftBounds, rightBounds);
    ASSERT_EQ(sides.left, 1u);
    ASSERT_EQ(sides.right, 1u);
    for (const PrimRecord& part : {left, right}) {
        EXPECT_EQ(part.sceneIndex, 1u);
        EXPECT_EQ(std::bit_cast<uint32_t>(part.zero), 0u); // PrimRecord: lane 3, upper corner
    }
    EXPECT_EQ(left.upper.x, -0.75f);
    EXPECT_EQ(right.lower.x, -0.75f);
    EXPECT_EQ(right.upper.y, 0.5f); // the triangle's edge at x = -0.75
}

// One record a triangle of the scene (its box and index), and the scene's box.
RecordVector recordsOf(const Scene& scene, Aabb& sceneBox) {
    RecordVector records;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        const glm::vec3 lower = glm::min(t.v0, glm::min(t.v1, t.v2));
        const glm::vec3 upper = glm::max(t.v0, glm::max(t.v1, t.v2));
        records.push_back({lower, static_cast<uint32_t>(i), upper, 0.0f});
        sceneBox.extend(lower);
        sceneBox.extend(upper);
    }
    return records;
}

// The top's spatial splits count each chunk's sides first and write them only if the split is
// kept (bvh_build_top.cpp): countSpatialSplit must give the sizes and bounds applySpatialSplit
// gives, chunk by chunk, and the chunks' parts written side by side must be the parts of the
// whole node, for planes through the scene, on its vertices and outside it.
TEST(BvhSpatialSplit, CountingGivesTheSidesThatWritingMakes) {
    const Scene scene = makeRoom(3000, 31);
    Aabb sceneBox;
    RecordVector records = recordsOf(scene, sceneBox);
    const auto sameBounds = [](const RecordBounds& a, const RecordBounds& b) {
        const Aabb boxes[2] = {a.box.toAabb(), b.box.toAabb()};
        const Aabb centres[2] = {a.centres.toAabb(), b.centres.toAabb()};
        return std::memcmp(&boxes[0], &boxes[1], sizeof(Aabb)) == 0 &&
               std::memcmp(&centres[0], &centres[1], sizeof(Aabb)) == 0;
    };
    const std::size_t n = records.size();
    int crossed = 0; // planes that cut some reference in two
    for (int axis = 0; axis < 3; ++axis) {
        const float lower = sceneBox.lower[axis], extent = sceneBox.upper[axis] - lower;
        for (const float position :
             {lower - 1.0f, lower + 0.31f * extent, lower + 0.5f * extent, records[7].lower[axis],
              scene.triangles[n - 1].v1[axis], sceneBox.upper[axis] + 1.0f}) {
            SpatialSplit split;
            split.axis = axis;
            split.position = position;
            SCOPED_TRACE(testing::Message() << "axis " << axis << " plane " << position);
            RecordVector wholeLeft(n), wholeRight(n);
            RecordBounds wholeLeftBounds, wholeRightBounds;
            const SpatialSides whole = applySpatialSplit(
                scene, records.data(), records.data() + n, split, 1e-6f, wholeLeft.data(),
                wholeRight.data(), wholeLeftBounds, wholeRightBounds);
            crossed += whole.left + whole.right > n ? 1 : 0;
            RecordVector left(n), right(n);
            std::size_t leftAt = 0, rightAt = 0;
            const std::size_t cuts[] = {0, 1, n / 3, n / 3 + 1, n - 5, n};
            for (std::size_t c = 0; c + 1 < std::size(cuts); ++c) {
                const PrimRecord *first = records.data() + cuts[c],
                                 *last = records.data() + cuts[c + 1];
                RecordBounds countedLeft, countedRight, writtenLeft, writtenRight;
                const SpatialSides counted =
                    countSpatialSplit(scene, first, last, split, 1e-6f, countedLeft, countedRight);
                const SpatialSides written =
                    applySpatialSplit(scene, first, last, split, 1e-6f, left.data() + leftAt,
                                      right.data() + rightAt, writtenLeft, writtenRight);
                ASSERT_EQ(counted.left, written.left) << "chunk " << c;
                ASSERT_EQ(counted.right, written.right) << "chunk " << c;
                EXPECT_TRUE(sameBounds(countedLeft, writtenLeft)) << "chunk " << c;
                EXPECT_TRUE(sameBounds(countedRight, writtenRight)) << "chunk " << c;
                leftAt += written.left;
                rightAt += written.right;
            }
            ASSERT_EQ(leftAt, whole.left);
            ASSERT_EQ(rightAt, whole.right);
            EXPECT_EQ(std::memcmp(left.data(), wholeLeft.data(), leftAt * sizeof(PrimRecord)), 0);
            EXPECT_EQ(std::memcmp(right.data(), wholeRight.data(), rightAt * sizeof(PrimRecord)),
                      0);
        }
    }
    EXPECT_GT(crossed, 3); // the room's quads cross most planes through it
}

// A whole node's spatial split writes both sides into its children's room, the right side from
// the room's end (applySpatialSplitInRoom, bvh_build_subtree.cpp): the same sides, bounds and
// order as written apart, in a room just large enough and in a larger one; in a room too small
// for both (a split the budget then turns down) still nothing outside the room is written.
TEST(BvhSpatialSplit, InOneRoomTheSidesAreThoseWrittenApart) {
    const Scene scene = makeRoom(2000, 37);
    Aabb sceneBox;
    RecordVector records = recordsOf(scene, sceneBox);
    const std::size_t n = records.size();
    constexpr std::size_t kGuard = 16; // records on each side of the room, never to be written
    PrimRecord canary{};
    std::memset(&canary, 0xA5, sizeof(canary));
    const auto boundsBytes = [](const RecordBounds& b) {
        const Aabb boxes[2] = {b.box.toAabb(), b.centres.toAabb()};
        std::vector<unsigned char> bytes(sizeof(boxes));
        std::memcpy(bytes.data(), boxes, sizeof(boxes));
        return bytes;
    };
    int tooSmall = 0; // rooms tried that could not hold both sides
    for (int axis = 0; axis < 3; ++axis) {
        const float lower = sceneBox.lower[axis], extent = sceneBox.upper[axis] - lower;
        for (const float position : {lower - 1.0f, lower + 0.27f * extent, lower + 0.5f * extent,
                                     records[11].upper[axis], sceneBox.upper[axis] + 1.0f}) {
            SCOPED_TRACE(testing::Message() << "axis " << axis << " plane " << position);
            SpatialSplit split;
            split.axis = axis;
            split.position = position;
            RecordVector apartLeft(n), apartRight(n);
            RecordBounds apartLeftBounds, apartRightBounds;
            const SpatialSides apart = applySpatialSplit(
                scene, records.data(), records.data() + n, split, 1e-6f, apartLeft.data(),
                apartRight.data(), apartLeftBounds, apartRightBounds);
            const std::size_t both = apart.left + apart.right;
            std::vector<std::size_t> sizes{both, both + 100};
            if (both > n) {
                sizes.push_back(n); // the least room the contract allows
                sizes.push_back(both - 1);
            }
            for (const std::size_t size : sizes) {
                SCOPED_TRACE(testing::Message() << "room " << size);
                std::vector<PrimRecord> memory(size + 2 * kGuard, canary);
                PrimRecord* room = memory.data() + kGuard;
                RecordBounds leftBounds, rightBounds;
                const SpatialSides made =
                    applySpatialSplitInRoom(scene, records.data(), records.data() + n, split, 1e-6f,
                                            room, size, leftBounds, rightBounds);
                ASSERT_EQ(made.left, apart.left);
                ASSERT_EQ(made.right, apart.right);
                EXPECT_EQ(boundsBytes(leftBounds), boundsBytes(apartLeftBounds));
                EXPECT_EQ(boundsBytes(rightBounds), boundsBytes(apartRightBounds));
                for (std::size_t g = 0; g < kGuard; ++g) {
                    ASSERT_EQ(std::memcmp(&memory[g], &canary, sizeof(canary)), 0) << g;
                    ASSERT_EQ(std::memcmp(&memory[kGuard + size + g], &canary, sizeof(canary)), 0)
                        << g;
                }
                if (size < both) {
                    ++tooSmall;
                    continue;
                }
                EXPECT_EQ(std::memcmp(room, apartLeft.data(), made.left * sizeof(PrimRecord)), 0);
                EXPECT_EQ(std::memcmp(room + (size - made.right), apartRight.data(),
                                      made.right * sizeof(PrimRecord)),
                          0);
            }
        }
    }
    EXPECT_GT(tooSmall, 3); // most planes through the room cut some reference in two
}

// binSpatial adds each reference to two ranges of bins and cuts the ranges' unions to the
// slabs only at the end; its bins must equal those of references cut to each bin's slab and
// added one by one, for references crossing any number of bins (1 to all 16), lying on planes
// and on the node's bounds, along each axis, every reference binned or every stride-th (a
// large node's sample), an even or odd number of them. Values compare with ==: only zeros'
// signs may differ between the two orders.
TEST(BvhSpatialSplit, BinsMatchReferencesCutOneByOne) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_int_distribution<int> planeIndex(0, kSpatialBins);
    const Aabb bounds{{-1.0f, 0.5f, 2.0f}, {3.0f, 1.75f, 2.3f}};
    int crossings[kSpatialBins + 1] = {}; // references by how many bins they cross
    for (int trial = 0; trial < 300; ++trial) {
        const int axis = trial % 3;
        const int count = 1 + trial % 41;
        const float lower = bounds.lower[axis], extent = bounds.upper[axis] - lower;
        RecordVector records;
        for (int i = 0; i < count; ++i) {
            // Each bound anywhere in the node, or on one of its planes (the node's bounds
            // included).
            glm::vec3 a, b;
            for (int k = 0; k < 3; ++k) {
                const float width = bounds.upper[k] - bounds.lower[k];
                a[k] = bounds.lower[k] + width * unit(rng);
                b[k] = bounds.lower[k] + width * unit(rng);
            }
            if (unit(rng) < 0.3f) {
                a[axis] = spatialPlane(lower, extent, planeIndex(rng));
            }
            if (unit(rng) < 0.3f) {
                b[axis] = spatialPlane(lower, extent, planeIndex(rng));
            }
            records.push_back({glm::min(a, b), static_cast<uint32_t>(i), glm::max(a, b), 0.0f});
        }
        const auto stride = static_cast<std::size_t>(1 + trial / 3 % 3);
        SpatialBins got;
        binSpatial(records.data(), records.data() + count, bounds, axis, got, stride);

        SpatialBins want;
        const float scale = static_cast<float>(kSpatialBins) / extent;
        for (std::size_t i = 0; i < records.size(); i += stride) {
            const PrimRecord& r = records[i];
            const int first = binOf(r.lower[axis], lower, scale, kSpatialBins);
            const int last = binOf(r.upper[axis], lower, scale, kSpatialBins);
            ++crossings[last - first + 1];
            ++want.entering[first];
            ++want.leaving[last];
            for (int bin = first; bin <= last; ++bin) {
                Aabb part{r.lower, r.upper};
                if (bin > 0) {
                    part.lower[axis] = std::max(part.lower[axis], spatialPlane(lower, extent, bin));
                }
                if (bin < kSpatialBins - 1) {
                    part.upper[axis] =
                        std::min(part.upper[axis], spatialPlane(lower, extent, bin + 1));
                }
                want.box[bin].extend(_mm_setr_ps(part.lower.x, part.lower.y, part.lower.z, 0.0f),
                                     _mm_setr_ps(part.upper.x, part.upper.y, part.upper.z, 0.0f));
            }
        }
        for (int bin = 0; bin < kSpatialBins; ++bin) {
            ASSERT_EQ(got.entering[bin], want.entering[bin]) << "trial " << trial;
            ASSERT_EQ(got.leaving[bin], want.leaving[bin]) << "trial " << trial;
            const Aabb g = got.box[bin].toAabb(), w = want.box[bin].toAabb();
            ASSERT_EQ(g.empty(), w.empty()) << "trial " << trial << " bin " << bin;
            if (!w.empty()) {
                ASSERT_EQ(g.lower, w.lower) << "trial " << trial << " bin " << bin;
                ASSERT_EQ(g.upper, w.upper) << "trial " << trial << " bin " << bin;
            }
        }
    }
    for (int n = 1; n <= kSpatialBins; ++n) {
        EXPECT_GT(crossings[n], 10) << "references crossing " << n << " bins";
    }
}

// Two clusters joined by a reference across the node: the best spatial split cuts between the
// clusters, the long reference going to both sides.
TEST(BvhSpatialSplit, BestSplitCutsBetweenClustersJoinedByALongReference) {
    RecordVector records;
    for (int i = 0; i < 10; ++i) {
        records.push_back(
            {{0.05f, 0.0f, 0.0f}, static_cast<uint32_t>(i), {0.1f, 0.05f, 0.05f}, 0.0f});
        records.push_back(
            {{0.9f, 0.0f, 0.0f}, static_cast<uint32_t>(10 + i), {0.95f, 0.05f, 0.05f}, 0.0f});
    }
    records.push_back({{0.0f, 0.0f, 0.0f}, 20, {1.0f, 0.05f, 0.05f}, 0.0f});
    const Aabb bounds{{0.0f, 0.0f, 0.0f}, {1.0f, 0.05f, 0.05f}};
    SpatialBins bins;
    binSpatial(records.data(), records.data() + records.size(), bounds, 0, bins);
    const SpatialSplit split = bestSpatialSplit(bins, bounds, 0);
    EXPECT_EQ(split.axis, 0);
    EXPECT_GT(split.position, 0.1f);
    EXPECT_LT(split.position, 0.9f);
    EXPECT_EQ(split.references, 22u);
}

// A large node's spatial split is chosen from every stride-th reference (bvh_build_subtree.cpp:
// 1,024 to 2,047 of them): on the room's 30,080 references, every 29th (1,038) and every 58th
// (519) find the plane that binning them all finds, along each axis, and estimate its cost
// and references within 5%.
TEST(BvhSpatialSplit, SampleFindsTheSplitOfAllReferences) {
    const Scene room = makeRoom(30000, 50);
    RecordVector records;
    for (const Triangle& t : room.triangles) {
        Aabb box;
        box.extend(t.v0);
        box.extend(t.v1);
        box.extend(t.v2);
        records.push_back({box.lower, static_cast<uint32_t>(records.size()), box.upper, 0.0f});
    }
    const PrimRecord* first = records.data();
    const PrimRecord* last = first + records.size();
    const Aabb bounds = boundsOf(first, last).box.toAabb();
    for (int axis = 0; axis < 3; ++axis) {
        SpatialBins all;
        binSpatial(first, last, bounds, axis, all);
        const SpatialSplit want = bestSpatialSplit(all, bounds, axis);
        ASSERT_EQ(want.axis, axis);
        for (const std::size_t samples : {1024, 512}) {
            const std::size_t stride = records.size() / samples;
            SpatialBins some;
            binSpatial(first, last, bounds, axis, some, stride);
            const SpatialSplit got = bestSpatialSplit(some, bounds, axis);
            const double toAll = static_cast<double>(records.size()) /
                                 static_cast<double>((records.size() + stride - 1) / stride);
            EXPECT_EQ(got.position, want.position) << "axis " << axis << ", stride " << stride;
            EXPECT_NEAR(got.cost * toAll, want.cost, 0.05 * want.cost) << "axis " << axis;
            EXPECT_NEAR(got.references * toAll, want.references, 0.05 * want.references);
        }
    }
}

// The references a spatial split made are kept when both sides hold some and the extra ones
// fit the budget; a split chosen from a sample must also be cheaper, counted on them, than the
// node's object split (the sample's boxes may miss references, so its cost is no bound).
TEST(BvhSpatialSplit, KeptOnlyWithinTheBudgetAndCheaperThanTheObjectSplitIfSampled) {
    RecordBounds unitBox, halfBox; // surface areas 6 and 4
    unitBox.add(_mm_setr_ps(0.0f, 0.0f, 0.0f, 0.0f), _mm_setr_ps(1.0f, 1.0f, 1.0f, 0.0f));
    halfBox.add(_mm_setr_ps(0.0f, 0.0f, 0.0f, 0.0f), _mm_setr_ps(0.5f, 1.0f, 1.0f, 0.0f));
    SplitChoice choice;
    choice.object.axis = 0;
    choice.object.cost = 6.0f * 100.0f; // as if two unit boxes of 50 references
    choice.spatial.axis = 0;
    const uint32_t count = 100, budget = 10;
    const float anyGain = 0.0f;
    // Two half boxes of 55: cost 4 * 110 = 440, 10 extra references.
    EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, anyGain, 55, halfBox, 55, halfBox));
    EXPECT_FALSE(keepsSpatialSplit(choice, count, budget - 1, anyGain, 55, halfBox, 55, halfBox));
    EXPECT_FALSE(
        keepsSpatialSplit(choice, count, budget, anyGain, 0, RecordBounds{}, 100, unitBox));
    EXPECT_FALSE(
        keepsSpatialSplit(choice, count, budget, anyGain, 100, unitBox, 0, RecordBounds{}));
    // Two unit boxes of 55 cost 660, more than the object split: kept only if not sampled.
    EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, anyGain, 55, unitBox, 55, unitBox));
    choice.spatial.sampled = true;
    EXPECT_FALSE(keepsSpatialSplit(choice, count, budget, anyGain, 55, unitBox, 55, unitBox));
    EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, anyGain, 55, halfBox, 55, halfBox));
    choice.object.axis = -1; // no object split to compare with
    EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, anyGain, 55, unitBox, 55, unitBox));
}

// With a least gain a reference, a split is kept where it lowers the object split's SAH cost by
// at least that many times the fraction of references it adds, sampled or not. Two half boxes
// of 55 references against 100 in the object split's: the cost falls by (600 - 440) / 600 =
// 26.7% for 10% more references, a gain of 2.67 a reference.
TEST(BvhSpatialSplit, KeptOnlyWhereTheCostFallsEnoughForTheReferencesAdded) {
    RecordBounds halfBox; // surface area 4
    halfBox.add(_mm_setr_ps(0.0f, 0.0f, 0.0f, 0.0f), _mm_setr_ps(0.5f, 1.0f, 1.0f, 0.0f));
    SplitChoice choice;
    choice.object.axis = 0;
    choice.object.cost = 6.0f * 100.0f;
    choice.spatial.axis = 0;
    const uint32_t count = 100, budget = 40;
    for (const bool sampled : {false, true}) {
        SCOPED_TRACE(sampled ? "sampled" : "not sampled");
        choice.spatial.sampled = sampled;
        EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, 0.5f, 55, halfBox, 55, halfBox));
        EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, 2.6f, 55, halfBox, 55, halfBox));
        EXPECT_FALSE(keepsSpatialSplit(choice, count, budget, 2.7f, 55, halfBox, 55, halfBox));
        // 64 a side: (600 - 512) / 600 = 14.7% for 28% more, a gain of 0.52 a reference.
        EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, 0.5f, 64, halfBox, 64, halfBox));
        EXPECT_FALSE(keepsSpatialSplit(choice, count, budget, 0.55f, 64, halfBox, 64, halfBox));
    }
    choice.object.axis = -1; // no object split to compare with
    EXPECT_TRUE(keepsSpatialSplit(choice, count, budget, 100.0f, 64, halfBox, 64, halfBox));
}

// Long thin triangles in every direction, as in scripts/outside_meshes.py's "sticks": every
// node's triangles reach across it, so spatial splits near the top cut about a tenth of the
// references for a few percent of the SAH cost. Without a least gain they take the budget;
// with the default one they are refused, while the room's wide quads (which cut few references
// for much) are still split (SplitsLargeTrianglesWithinTheBudget), and the answers stay brute
// force's.
Scene makeSticks(int count, uint32_t seed) {
    Scene scene;
    std::mt19937 rng(seed);
    std::normal_distribution<float> normal;
    std::uniform_real_distribution<float> inCube(-5.0f, 5.0f), length(2.0f, 8.0f);
    while (scene.triangles.size() < static_cast<std::size_t>(count)) {
        const glm::vec3 d = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
        const glm::vec3 a(inCube(rng), inCube(rng), inCube(rng));
        const glm::vec3 b = a + length(rng) * d;
        if (glm::any(glm::greaterThan(glm::abs(b), glm::vec3(5.0f)))) {
            continue; // both ends in the cube
        }
        glm::vec3 leastAxis(0.0f); // of d's: never parallel to d
        const glm::vec3 m = glm::abs(d);
        leastAxis[m.x <= m.y && m.x <= m.z ? 0 : (m.y <= m.z ? 1 : 2)] = 1.0f;
        const glm::vec3 across = glm::normalize(glm::cross(d, leastAxis));
        scene.triangles.push_back({a, b, 0.5f * (a + b) + 0.02f * across, 0});
    }
    return scene;
}

TEST(BvhSpatialSplit, LeastGainRefusesSplitsThatAddManyReferencesForLittle) {
    const Scene sticks = makeSticks(8000, 61);
    BvhBuildOptions anyGain = spatialOnly(0.3f);
    anyGain.spatialSplitMinGain = 0.0f;
    const BvhBuildOptions byDefault = spatialOnly(0.3f);
    const Bvh many = buildBvh(sticks, anyGain), few = buildBvh(sticks, byDefault);
    const double triangles = static_cast<double>(sticks.triangles.size());
    std::printf("sticks: %.3f references a triangle at any gain, %.3f by default\n",
                static_cast<double>(many.leafReferences) / triangles,
                static_cast<double>(few.leafReferences) / triangles);
    EXPECT_GT(static_cast<double>(many.leafReferences), 1.05 * triangles);
    EXPECT_LT(static_cast<double>(few.leafReferences), 1.02 * triangles);
    EXPECT_LT(few.memoryBytes(), many.memoryBytes());
    EXPECT_GT(expectMatchesBruteForce(sticks, few, makeRandomRays(2000, 62)), 200);
}

// binOverreach, the test for trying spatial splits at all: about 0 where references are small
// against their bins (a finely tessellated surface), 1 or more where they cross bins.
float overreachOf(const RecordVector& records) {
    const RecordBounds bounds = boundsOf(records.data(), records.data() + records.size());
    const ObjectSplit frame = objectBinFrame(bounds.centres.toAabb(), 16);
    BinSet bins;
    bins.reset(frame.bins);
    binRecords(records.data(), records.data() + records.size(), frame.lower, frame.scale,
               frame.bins, bins);
    return binOverreach(bins, frame, bounds.box.toAabb());
}

TEST(BvhSpatialSplit, TriedOnlyWhereReferencesReachBeyondTheirBins) {
    RecordVector records;
    auto add = [&](float lower, float upper) {
        records.push_back({{lower, 0.0f, 0.0f},
                           static_cast<uint32_t>(records.size()),
                           {upper, 0.001f, 0.001f},
                           0.0f});
    };
    for (int i = 0; i < 64; ++i) {
        add(static_cast<float>(i) / 64.0f, static_cast<float>(i) / 64.0f + 0.001f);
    }
    EXPECT_LT(overreachOf(records), 0.1f);
    add(0.0f, 0.5f); // three references across half the node, in different bins
    add(0.25f, 0.75f);
    add(0.5f, 1.0f);
    EXPECT_GE(overreachOf(records), 1.0f);
}

// binOverreach against its definition, the sums taken axis by axis in bin order: on records of
// random sizes (some much longer on one axis than the others, some flat on an axis), with
// empty bins among used ones, and a binned axis of each kind.
TEST(BvhSpatialSplit, OverreachIsTheLargestSumOfBinExtentsOverTheNode) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int positive = 0, flatAxes = 0;
    for (int trial = 0; trial < 200; ++trial) {
        RecordVector records;
        const int count = 2 + trial % 50;
        const int longAxis = trial % 3, flatAxis = (trial / 3) % 4; // 3: none flat
        for (int i = 0; i < count; ++i) {
            glm::vec3 lower, size;
            for (int a = 0; a < 3; ++a) {
                lower[a] = a == flatAxis ? 0.5f : unit(rng) * unit(rng);
                size[a] = a == flatAxis ? 0.0f : 0.05f * unit(rng);
            }
            size[longAxis] = longAxis == flatAxis ? 0.0f : size[longAxis] + unit(rng) * 0.6f;
            records.push_back({lower, static_cast<uint32_t>(i), lower + size, 0.0f});
        }
        const RecordBounds bounds = boundsOf(records.data(), records.data() + count);
        const ObjectSplit frame = objectBinFrame(bounds.centres.toAabb(), 16);
        BinSet bins;
        bins.reset(frame.bins);
        binRecords(records.data(), records.data() + count, frame.lower, frame.scale, frame.bins,
                   bins);
        const Aabb box = bounds.box.toAabb();
        float want = 0.0f;
        for (int a = 0; a < 3; ++a) {
            if (!(frame.scale[a] > 0.0f)) {
                ++flatAxes;
                continue;
            }
            float sum = 0.0f;
            for (int b = 0; b < frame.bins; ++b) {
                if (bins.count[a][b] != 0) {
                    const Aabb part = bins.box[a][b].toAabb();
                    sum += part.upper[a] - part.lower[a];
                }
            }
            want = std::max(want, sum / (box.upper[a] - box.lower[a]) - 1.0f);
        }
        positive += want > 0.0f ? 1 : 0;
        ASSERT_EQ(binOverreach(bins, frame, box), want) << "trial " << trial;
    }
    EXPECT_GT(positive, 100);
    EXPECT_GT(flatAxes, 40);
}

// The references' two ranges hold room for every reference the splits may add, allocated
// once: a budget above 1 would need more, and is taken as 1.
TEST(BvhSpatialSplit, BudgetAboveOneIsTakenAsOne) {
    const Scene scene = makeRoom(3000, 53);
    const Bvh one = buildBvh(scene, spatialOnly(1.0f)), four = buildBvh(scene, spatialOnly(4.0f));
    EXPECT_GT(one.leafReferences, scene.triangles.size());
    EXPECT_LE(one.leafReferences, 2 * scene.triangles.size());
    EXPECT_EQ(four.leafReferences, one.leafReferences);
    ASSERT_EQ(four.wideNodes.size(), one.wideNodes.size());
    EXPECT_EQ(std::memcmp(four.wideNodes.data(), one.wideNodes.data(),
                          one.wideNodes.size() * sizeof(BvhWideNode)),
              0);
}

// A node whose budget is under a twentieth of its references tries no spatial split, and as
// the budget is shared by size, neither does its subtree (but where sharing's rounding gives a
// child a reference more than its part): a root budget of 3% gives no extra references, one of
// 6% some.
TEST(BvhSpatialSplit, BudgetUnderATwentiethTriesNone) {
    expectSplitsOnlyFrom(makeRoom(3000, 53), 0.03f, 0.06f);
}

// A split's children take their parts of the parent's two ranges: each child's references
// and spare room are followed by room for its share of the budget, and the two rooms fill the
// parent's exactly, without overlapping.
TEST(BvhSpatialSplit, ChildrenShareTheParentsRoom) {
    BuildTask parent;
    parent.count = 100;
    parent.splitBudget = 30;
    BuildTask left, right;
    RecordVector to(parent.room()), from(parent.room());
    // A spatial split that made 10 extra references.
    placeChildren(parent, 55, 55, to.data(), from.data(), left, right);
    EXPECT_EQ(left.count, 55u);
    EXPECT_EQ(right.count, 55u);
    EXPECT_EQ(left.splitBudget + right.splitBudget, 20u);
    EXPECT_EQ(left.splitBudget, 10u); // by size
    EXPECT_EQ(left.room() + right.room(), parent.room());
    EXPECT_EQ(left.first, to.data());
    EXPECT_EQ(left.spare, from.data());
    EXPECT_EQ(right.first, to.data() + left.room());
    EXPECT_EQ(right.spare, from.data() + left.room());

    // An object split: the whole budget left, shared by size.
    placeChildren(parent, 80, 20, to.data(), from.data(), left, right);
    EXPECT_EQ(left.splitBudget, 24u);
    EXPECT_EQ(right.splitBudget, 6u);
    // Over budget (kept only by a caller that checked): no room to share.
    placeChildren(parent, 70, 70, to.data(), from.data(), left, right);
    EXPECT_EQ(left.splitBudget + right.splitBudget, 0u);
}

// Nodes whose centroids all coincide split at the median, in place; with a budget their right
// half moves on to leave the left half its room. Thousands of copies of one wide triangle
// among the room's: median splits at the top (on the team) and in the subtrees, spatial splits
// around them, and still brute force's answers and one tree for any thread count.
TEST(BvhSpatialSplit, MedianSplitsKeepTheirChildrensRoom) {
    Scene scene = makeRoom(3000, 54);
    const Triangle wide{{-1.0f, -0.2f, -1.0f}, {1.0f, 0.1f, -1.0f}, {0.0f, 0.3f, 1.0f}, 0};
    scene.triangles.insert(scene.triangles.end(), 6000, wide);
    BvhBuildOptions one = spatialOnly(0.3f), two = spatialOnly(0.3f);
    one.threads = 1;
    two.threads = 2;
    const Bvh a = buildBvh(scene, one), b = buildBvh(scene, two);
    EXPECT_GT(a.leafReferences, scene.triangles.size());
    EXPECT_LE(a.leafReferences, scene.triangles.size() + scene.triangles.size() * 3 / 10);
    EXPECT_GT(expectMatchesBruteForce(scene, a, makeRandomRays(3000, 55)), 500);
    ASSERT_EQ(a.triangleBlocks.size(), b.triangleBlocks.size());
    EXPECT_EQ(std::memcmp(a.triangleBlocks.data(), b.triangleBlocks.data(),
                          a.triangleBlocks.size() * sizeof(BvhTriangleBlock)),
              0);
}

TEST(BvhSpatialSplit, SameTreeForAnyThreadCount) {
    const Scene scene = makeRoom(30000, 48); // big enough for parallel subtrees
    BvhBuildOptions one = spatialOnly(0.3f), two = spatialOnly(0.3f);
    one.threads = 1;
    two.threads = 2;
    one.keepBinaryNodes = two.keepBinaryNodes = true; // both forms
    const Bvh a = buildBvh(scene, one), b = buildBvh(scene, two);
    ASSERT_FALSE(a.nodes.empty());
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)), 0);
    ASSERT_EQ(a.triangleBlocks.size(), b.triangleBlocks.size());
    EXPECT_EQ(std::memcmp(a.triangleBlocks.data(), b.triangleBlocks.data(),
                          a.triangleBlocks.size() * sizeof(BvhTriangleBlock)),
              0);
}

} // namespace
} // namespace raylab::accel_test
