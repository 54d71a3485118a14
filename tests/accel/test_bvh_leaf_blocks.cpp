// Leaves of the 8-wide BVH share triangle blocks (bvh_collapse.cpp): every leaf triangle has
// one lane of its own, the lanes no leaf takes repeat their block's first triangle, the blocks
// are fuller than one leaf a block would make them, and the answers are brute force's.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/bvh/bvh_wide.h"

#include <gtest/gtest.h>
#include <vector>

namespace raylab::accel_test {
namespace {

// The binary leaves (kept) point at their triangles' lanes: slots [index, index + count).
void expectOneLaneEach(const Scene& scene) {
    BvhBuildOptions keep;
    keep.keepBinaryNodes = true;
    const Bvh bvh = buildBvh(scene, keep);
    if (bvh.wideNodes.empty()) {
        GTEST_SKIP() << "this CPU has no AVX2: there are no triangle blocks";
    }
    const std::size_t slots = bvh.triangleBlocks.size() * kWideLanes;
    std::vector<int> owners(slots, 0);
    std::size_t references = 0;
    for (const BvhNode& node : bvh.nodes) {
        if (!node.isLeaf()) {
            continue;
        }
        for (uint32_t i = node.index; i < node.index + node.count; ++i) {
            ASSERT_LT(i, slots);
            ++owners[i];
            ++references;
        }
    }
    EXPECT_EQ(references, bvh.leafReferences);
    std::size_t spare = 0;
    for (std::size_t s = 0; s < slots; ++s) {
        ASSERT_LE(owners[s], 1) << "lane " << s << " holds two leaf triangles";
        if (owners[s] == 0) {
            const BvhTriangleBlock& block = bvh.triangleBlocks[s / kWideLanes];
            EXPECT_EQ(block.sceneIndex[s % kWideLanes], block.sceneIndex[0]) << "lane " << s;
            ++spare;
        }
    }
    // One leaf a block left the dragon's blocks 5.7 of 8 lanes full; shared, 7.0.
    const double lanesPerBlock =
        static_cast<double>(references) / static_cast<double>(bvh.triangleBlocks.size());
    EXPECT_GT(lanesPerBlock, 6.5) << spare << " spare lanes in " << bvh.triangleBlocks.size()
                                  << " blocks";
}

TEST(BvhLeafBlocks, SphereLeavesTakeOneLaneEachInFullBlocks) {
    expectOneLaneEach(makeClosedSphere(120, 160, 1.0f, 0.01f, 4));
}

TEST(BvhLeafBlocks, SoupLeavesTakeOneLaneEachInFullBlocks) {
    expectOneLaneEach(makeTriangleSoup(30000, 0.03f, 5));
}

TEST(BvhLeafBlocks, SharedBlocksGiveBruteForceAnswers) {
    const Scene scene = makeClosedSphere(60, 80, 1.0f, 0.02f, 6);
    EXPECT_GT(expectMatchesBruteForce(scene, buildBvh(scene), makeRandomRays(20000, 7)), 1000);
}

} // namespace
} // namespace raylab::accel_test
