// The parallel build (core/bvh_build.cpp): the same bytes whatever the thread count, with the
// top of the tree split by chunks on several threads (large nodes, spatial splits and
// pre-splits included), the same answers as brute force, the same bytes again when rebuilt in
// kept memory (rebuildBvh), and its parts: the build's thread team and the SSE clipping of
// triangles at a plane.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/bvh/build/bvh_build_clip.h"
#include "core/bvh/build/bvh_build_memory.h"
#include "core/bvh/build/bvh_build_team.h"
#include "core/bvh/build/bvh_clip.h"
#include "core/bvh/build/bvh_slot_array.h"

#include <atomic>
#include <cstring>
#include <gtest/gtest.h>
#include <iterator>
#include <random>
#include <vector>

namespace raylab::accel_test {
namespace {

// Small triangles among large slanted quads that cross the whole scene: big enough for nodes
// split by chunks (more than 16,384 references) and for spatial splits near the root.
Scene makeCluttered(int smallCount, uint32_t seed) {
    Scene scene = makeTriangleSoup(smallCount, 0.03f, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < 60; ++i) {
        const glm::vec3 a{unit(rng), unit(rng), unit(rng)};
        const glm::vec3 b{-a.x, unit(rng), -a.z};
        const glm::vec3 c{unit(rng), -a.y, unit(rng)};
        scene.triangles.push_back({a, b, c, 0});
    }
    return scene;
}

// x and y hold the same bytes (memcmp must not see the null pointer of an empty vector).
template <typename Vector> bool sameBytes(const Vector& x, const Vector& y) {
    using T = typename Vector::value_type;
    return x.size() == y.size() &&
           (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(T)) == 0);
}

void expectSameBytes(const Bvh& a, const Bvh& b) {
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_TRUE(sameBytes(a.nodes, b.nodes));
    ASSERT_EQ(a.wideNodes.size(), b.wideNodes.size());
    for (std::size_t i = 0; i < a.wideNodes.size(); ++i) { // the data, not the padding
        const BvhWideNode &x = a.wideNodes[i], &y = b.wideNodes[i];
        ASSERT_EQ(std::memcmp(x.lower, y.lower, sizeof(x.lower)), 0) << i;
        ASSERT_EQ(std::memcmp(x.upper, y.upper, sizeof(x.upper)), 0) << i;
        ASSERT_EQ(std::memcmp(x.child, y.child, sizeof(x.child)), 0) << i;
    }
    EXPECT_TRUE(sameBytes(a.triangleBlocks, b.triangleBlocks));
    EXPECT_TRUE(sameBytes(a.triangles, b.triangles));
    EXPECT_EQ(a.leafReferences, b.leafReferences);
    EXPECT_EQ(a.skippedTriangles, b.skippedTriangles);
}

TEST(BvhBuild, SameBytesForAnyThreadCount) {
    const Scene scene = makeCluttered(90000, 3);
    BvhBuildOptions options;
    options.threads = 1;
    const Bvh one = buildBvh(scene, options);
    EXPECT_GT(one.leafReferences, scene.triangles.size()); // pre-splits or spatial splits
    for (const int threads : {2, 3, 8}) {
        options.threads = threads;
        SCOPED_TRACE(threads);
        expectSameBytes(one, buildBvh(scene, options));
    }
}

TEST(BvhBuild, SameBytesForAnyThreadCountInTheScalarForm) {
    const Scene scene = makeCluttered(40000, 4);
    BvhBuildOptions options;
    options.simd = false;
    options.threads = 1;
    const Bvh one = buildBvh(scene, options);
    ASSERT_TRUE(one.wideNodes.empty());
    options.threads = 4;
    expectSameBytes(one, buildBvh(scene, options));
}

TEST(BvhBuild, SameBytesForAnyThreadCountWithoutSplits) {
    const Scene scene = makeTriangleSoup(70000, 0.02f, 5);
    BvhBuildOptions options;
    options.presplitBudget = 0.0f;
    options.spatialSplitBudget = 0.0f;
    options.threads = 1;
    const Bvh one = buildBvh(scene, options);
    EXPECT_EQ(one.leafReferences, scene.triangles.size());
    options.threads = 2;
    expectSameBytes(one, buildBvh(scene, options));
}

TEST(BvhBuild, ParallelBuildMatchesBruteForce) {
    const Scene scene = makeCluttered(60000, 6);
    BvhBuildOptions options;
    options.threads = 3;
    const Bvh bvh = buildBvh(scene, options);
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(1500, 7)), 300);
    expectMatchesBruteForce(scene, bvh, makeAxisAlignedRays(500, 1.5f, 8));
}

TEST(BvhBuild, EveryLeafReferenceOnceAndBoxesNested) {
    const Scene scene = makeCluttered(50000, 9);
    BvhBuildOptions options;
    options.simd = false;
    options.threads = 2;
    const Bvh bvh = buildBvh(scene, options);
    std::vector<int> seen(bvh.leafReferences, 0);
    for (const BvhNode& node : bvh.nodes) {
        if (node.isLeaf()) {
            for (uint32_t i = node.index; i < node.index + node.count; ++i) {
                ASSERT_LT(i, seen.size());
                ++seen[i];
            }
            continue;
        }
        for (const uint32_t c : {node.index, node.index + 1}) {
            ASSERT_LT(c, bvh.nodes.size());
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(node.lower[a], bvh.nodes[c].lower[a]);
                EXPECT_GE(node.upper[a], bvh.nodes[c].upper[a]);
            }
        }
    }
    for (const int n : seen) {
        ASSERT_EQ(n, 1);
    }
}

// rebuildBvh into one Bvh and one BvhBuildMemory, scene after scene, larger and smaller, with
// and without the binary nodes, the 8-wide form, splits and pre-splits, and an empty scene: each
// time the bytes of a fresh build, whatever the arrays held before.
TEST(BvhRebuild, SameBytesAsAFreshBuildWhateverItHeldBefore) {
    const Scene cluttered = makeCluttered(60000, 11);
    const Scene soup = makeTriangleSoup(20000, 0.05f, 12);
    BvhBuildOptions wide, binaryKept, scalar, presplit;
    wide.threads = binaryKept.threads = scalar.threads = presplit.threads = 2;
    binaryKept.keepBinaryNodes = true;
    scalar.simd = false;
    presplit.presplitBudget = 0.3f;
    const struct {
        const Scene* scene;
        const BvhBuildOptions* options;
    } builds[] = {{&cluttered, &wide},  {&soup, &binaryKept}, {&cluttered, &scalar},
                  {&soup, &wide},       {&cluttered, &wide},  {&cluttered, &presplit},
                  {&soup, &binaryKept}, {&cluttered, &wide}};
    const Scene empty;
    BvhBuildMemory memory;
    Bvh bvh;
    for (std::size_t i = 0; i < std::size(builds); ++i) {
        SCOPED_TRACE(i);
        rebuildBvh(*builds[i].scene, *builds[i].options, memory, bvh);
        const Bvh fresh = buildBvh(*builds[i].scene, *builds[i].options);
        expectSameBytes(bvh, fresh);
        EXPECT_EQ(bvh.boxPad, fresh.boxPad);
        EXPECT_EQ(bvh.largestCoordinate, fresh.largestCoordinate);
        EXPECT_GE(bvh.memoryBytes(), fresh.memoryBytes());
        EXPECT_GT(memory.bytes(), builds[i].scene->triangles.size() * 2 * sizeof(float[8]));
        if (i == 3) { // an empty scene between the others
            rebuildBvh(empty, wide, memory, bvh);
            EXPECT_TRUE(bvh.nodes.empty() && bvh.wideNodes.empty() && bvh.triangles.empty());
            EXPECT_EQ(bvh.leafReferences, 0u);
            EXPECT_FALSE(closestHit(bvh, Ray{{0, 0, -5}, {0, 0, 1}}).found());
        }
    }
    expectMatchesBruteForce(cluttered, bvh, makeRandomRays(800, 13));
}

// A rebuild of the same scene allocates nothing: the Bvh's arrays stay where they were and the
// memory holds what it held.
TEST(BvhRebuild, SameSceneReusesEveryArray) {
    const Scene scene = makeCluttered(40000, 14);
    BvhBuildOptions options;
    options.threads = 2;
    BvhBuildMemory memory;
    EXPECT_EQ(memory.bytes(), 0u);
    Bvh bvh;
    rebuildBvh(scene, options, memory, bvh);
    ASSERT_FALSE(bvh.wideNodes.empty());
    const BvhWideNode* nodes = bvh.wideNodes.data();
    const BvhTriangleBlock* blocks = bvh.triangleBlocks.data();
    const std::size_t held = memory.bytes();
    const std::size_t bvhBytes = bvh.memoryBytes();
    rebuildBvh(scene, options, memory, bvh);
    EXPECT_EQ(bvh.wideNodes.data(), nodes);
    EXPECT_EQ(bvh.triangleBlocks.data(), blocks);
    EXPECT_EQ(memory.bytes(), held);
    EXPECT_EQ(bvh.memoryBytes(), bvhBytes);
    expectSameBytes(bvh, buildBvh(scene, options));
}

// The memory keeps the build's threads: a rebuild on as many threads takes the same team, one
// on another count a new team of that many; a scene too small for more than one thread leaves the
// team alone. The trees are a fresh build's each time.
TEST(BvhRebuild, KeepsItsThreadsFromOneBuildToTheNext) {
    const Scene scene = makeCluttered(40000, 16);
    const Scene small = makeTriangleSoup(500, 0.05f, 17);
    BvhBuildOptions two, three;
    two.threads = 2;
    three.threads = 3;
    BvhBuildMemory memory;
    Bvh bvh;
    // How many loops the kept team has run (a new team starts from none).
    const auto loops = [&] {
        const BuildTeam* team = memory.arrays().team.get();
        return team ? team->loopsShared() : 0ul;
    };
    rebuildBvh(scene, two, memory, bvh);
    ASSERT_NE(memory.arrays().team, nullptr);
    EXPECT_EQ(memory.arrays().team->size(), 2);
    const unsigned long perBuild = loops();
    ASSERT_GT(perBuild, 0ul);
    rebuildBvh(scene, two, memory, bvh);
    EXPECT_EQ(loops(), 2 * perBuild); // the same team, the same loops again
    expectSameBytes(bvh, buildBvh(scene, two));
    rebuildBvh(scene, three, memory, bvh);
    ASSERT_NE(memory.arrays().team, nullptr);
    EXPECT_EQ(memory.arrays().team->size(), 3);
    EXPECT_EQ(loops(), perBuild); // a new team
    expectSameBytes(bvh, buildBvh(scene, three));
    rebuildBvh(small, three, memory, bvh); // on one thread, the team of three left as it was
    EXPECT_EQ(memory.arrays().team->size(), 3);
    EXPECT_EQ(loops(), perBuild);
    expectSameBytes(bvh, buildBvh(small, three));
    rebuildBvh(scene, three, memory, bvh);
    EXPECT_EQ(loops(), 2 * perBuild);
    expectSameBytes(bvh, buildBvh(scene, three));
}

// A memory moved from still builds (it starts empty again).
TEST(BvhRebuild, MemoryMovedFromStillBuilds) {
    const Scene scene = makeTriangleSoup(9000, 0.05f, 15);
    BvhBuildMemory memory;
    Bvh bvh;
    rebuildBvh(scene, {}, memory, bvh);
    BvhBuildMemory taken = std::move(memory);
    EXPECT_GT(taken.bytes(), 0u);
    rebuildBvh(scene, {}, memory, bvh); // NOLINT(bugprone-use-after-move): the case tested
    expectSameBytes(bvh, buildBvh(scene));
}

// Slots hold at least what they were asked for, one after another, each starting on a 64-byte
// boundary of the shared array, whatever the element's size (28 bytes: every 16 elements).
TEST(SlotLayout, SlotsFollowEachOtherOnCacheLineBoundaries) {
    struct Element28 {
        uint32_t words[7];
    };
    SlotLayout<Element28> layout;
    const std::size_t asked[] = {0, 1, 15, 16, 17, 100};
    for (const std::size_t n : asked) {
        layout.append(n);
    }
    for (std::size_t i = 0; i < std::size(asked); ++i) {
        EXPECT_EQ(layout.begin(i) * sizeof(Element28) % 64, 0u) << i;
        EXPECT_GE(layout.begin(i + 1) - layout.begin(i), asked[i]) << i;
        EXPECT_LT(layout.begin(i + 1) - layout.begin(i), asked[i] + 16) << i;
    }
    EXPECT_EQ(layout.total(), layout.begin(std::size(asked)));
    EXPECT_EQ(layout.total(), std::size_t{0 + 16 + 16 + 16 + 32 + 112});
}

// A SlotArray fills its slot and nothing beyond it, then moves its elements to memory of its own.
TEST(SlotArray, GrowsOutOfItsSlotKeepingItsElements) {
    constexpr uint32_t kCanary = 0xdeadbeefu;
    std::vector<uint32_t> memory(12, kCanary);
    SlotArray<uint32_t> a(memory.data(), 8);
    for (uint32_t i = 0; i < 8; ++i) {
        a.push_back(i);
    }
    EXPECT_TRUE(a.inSlot());
    EXPECT_EQ(a.data(), memory.data());
    for (uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(memory[i], i);
    }
    a.push_back(8);
    EXPECT_FALSE(a.inSlot());
    a.resize(100);
    for (uint32_t i = 0; i < 9; ++i) {
        EXPECT_EQ(a[i], i);
    }
    for (std::size_t i = 8; i < memory.size(); ++i) {
        EXPECT_EQ(memory[i], kCanary) << i; // never written past the slot
    }
    SlotArray<uint32_t> b = std::move(a);
    EXPECT_EQ(b.size(), 100u);
    EXPECT_EQ(b[5], 5u);
    EXPECT_EQ(a.size(), 0u); // NOLINT(bugprone-use-after-move): the state moved from is tested
    SlotArray<uint32_t> unslotted;
    unslotted.resize(3);
    unslotted[2] = 7;
    EXPECT_EQ(unslotted[2], 7u);
}

// Leaves of one reference: each subtree makes twice as many nodes as its references, more than
// its slot holds (bvh_build.cpp, subtreeSlots; enough triangles for the slots' shared array to
// take huge pages, as they must to be used), and its nodes move out of the slot mid-build.
TEST(BvhBuild, SubtreesThatOutgrowTheirSlotsStillBuildTheTree) {
    const Scene scene = makeTriangleSoup(80000, 0.02f, 16);
    BvhBuildOptions options;
    options.simd = false;
    options.maxLeafSize = 1;
    options.threads = 1;
    const Bvh one = buildBvh(scene, options);
    ASSERT_FALSE(one.nodes.empty());
    std::size_t leaves = 0;
    for (const BvhNode& node : one.nodes) {
        if (node.isLeaf()) {
            ASSERT_EQ(node.count, 1u);
            ++leaves;
        }
    }
    EXPECT_EQ(leaves, one.leafReferences);
    EXPECT_EQ(one.nodes.size(), 2 * leaves - 1);
    options.threads = 2;
    expectSameBytes(one, buildBvh(scene, options));
    expectMatchesBruteForce(scene, one, makeRandomRays(800, 17));
}

// Enough triangles for the subtrees' two shared arrays (subtreeSlots, 2 MiB of leaf references
// and more of nodes) and the wide subtrees' two (bvh_collapse.cpp, partSlots) to take huge pages,
// so that every part is built in its slots: the same bytes on any thread count, and rebuilt in
// the memory of a smaller scene's build, whose parts had none.
TEST(BvhBuild, SubtreesInSharedSlotsGiveTheSameBytes) {
    const Scene scene = makeTriangleSoup(560000, 0.004f, 18);
    BvhBuildOptions options;
    options.threads = 1;
    const Bvh one = buildBvh(scene, options);
    options.threads = 2;
    BvhBuildMemory memory;
    Bvh bvh;
    rebuildBvh(makeTriangleSoup(6000, 0.05f, 19), options, memory, bvh);
    const BvhBuildMemory::Arrays& kept = memory.arrays();
    EXPECT_TRUE(kept.subtreeNodes.empty() && kept.collapse.nodes.empty()); // too small
    rebuildBvh(scene, options, memory, bvh);
    EXPECT_FALSE(kept.subtreeNodes.empty() || kept.subtreeLeaves.empty());
    EXPECT_FALSE(kept.collapse.nodes.empty() || kept.collapse.leaves.empty());
    expectSameBytes(one, bvh);
}

TEST(BuildTeam, RunsEveryIndexExactlyOnce) {
    for (const int threads : {1, 2, 5}) {
        BuildTeam team(threads);
        EXPECT_EQ(team.size(), threads);
        for (const std::size_t count : {0u, 1u, 2u, 7u, 1000u, 3u}) {
            std::vector<std::atomic<int>> runs(count);
            team.forEach(count, [&](std::size_t i) { runs[i].fetch_add(1); });
            for (std::size_t i = 0; i < count; ++i) {
                ASSERT_EQ(runs[i].load(), 1) << "threads " << threads << " count " << count;
            }
        }
    }
}

// The scalar splitBox as it was before the SSE form: the reference for splitBoxSse.
void splitBoxReference(const Triangle& t, const Aabb& box, int axis, float position, float slack,
                       Aabb& left, Aabb& right) {
    const glm::vec3 v[3] = {t.v0, t.v1, t.v2};
    left = Aabb{};
    right = Aabb{};
    for (int i = 0; i < 3; ++i) {
        const glm::vec3& p = v[i];
        const glm::vec3& q = v[(i + 1) % 3];
        if (p[axis] <= position) {
            left.extend(p);
        }
        if (p[axis] >= position) {
            right.extend(p);
        }
        if ((p[axis] < position && q[axis] > position) ||
            (p[axis] > position && q[axis] < position)) {
            glm::vec3 x = p + (position - p[axis]) / (q[axis] - p[axis]) * (q - p);
            x[axis] = position;
            left.extend(x);
            right.extend(x);
        }
    }
    for (Aabb* b : {&left, &right}) {
        if (b->empty()) {
            continue;
        }
        b->lower = glm::max(b->lower - glm::vec3(slack), box.lower);
        b->upper = glm::min(b->upper + glm::vec3(slack), box.upper);
    }
    left.upper[axis] = std::min(left.upper[axis], position);
    right.lower[axis] = std::max(right.lower[axis], position);
}

TEST(BvhBuild, SseClippingGivesTheScalarBoxesBitForBit) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    int crossing = 0;
    for (int n = 0; n < 20000; ++n) {
        Triangle t{{unit(rng), unit(rng), unit(rng)},
                   {unit(rng), unit(rng), unit(rng)},
                   {unit(rng), unit(rng), unit(rng)},
                   0};
        if (n % 7 == 0) {
            t.v1.y = t.v0.y; // an edge on an axis plane
        }
        Aabb box;
        box.extend(t.v0);
        box.extend(t.v1);
        box.extend(t.v2);
        if (n % 3 == 0) { // a part of the triangle's box, as spatial splits clip it
            box.lower.x = std::max(box.lower.x, unit(rng) * 0.5f);
        }
        const int axis = n % 3;
        const float position = n % 11 == 0 ? t.v0[axis] : unit(rng);
        const float slack = n % 2 == 0 ? 0.0f : 1e-6f;
        Aabb expectedLeft, expectedRight, left, right;
        splitBoxReference(t, box, axis, position, slack, expectedLeft, expectedRight);
        splitBox(t, box, axis, position, slack, left, right);
        ASSERT_EQ(std::memcmp(&left, &expectedLeft, sizeof(Aabb)), 0) << n;
        ASSERT_EQ(std::memcmp(&right, &expectedRight, sizeof(Aabb)), 0) << n;
        crossing += !left.empty() && !right.empty() ? 1 : 0;
    }
    EXPECT_GT(crossing, 2000);
}

} // namespace
} // namespace raylab::accel_test
