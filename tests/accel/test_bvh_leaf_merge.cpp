// Small nodes left unsplit when only the 8-wide form is kept (BuildContext::leafAtMost,
// kLeafMerge in bvh_collapse.h): the binary builder never splits a node of at most kLeafMerge
// references, and the wide tree is the one the collapse makes of the fully split binary tree
// (the same nodes, boxes and triangles per leaf), only its lanes in another order and without
// the spatial splits' copies inside a leaf.

#include "accel_check.h"
#include "accel_scenes.h"
#include "core/bvh/build/bvh_build_subtree.h"
#include "core/bvh/build/bvh_collapse.h"

#include <algorithm>
#include <cstring>
#include <gtest/gtest.h>
#include <random>
#include <set>
#include <vector>

namespace raylab::accel_test {
namespace {

// References of the subtree under each node of a built subtree.
std::vector<uint32_t> referencesUnder(const Subtree& tree) {
    std::vector<uint32_t> under(tree.nodes.size(), 0);
    for (std::size_t i = tree.nodes.size(); i-- > 0;) { // children follow their parent
        const BvhNode& n = tree.nodes[i];
        under[i] = n.isLeaf() ? n.count : under[n.index] + under[n.index + 1];
    }
    return under;
}

Subtree buildWithLeafAtMost(const Scene& scene, uint32_t leafAtMost) {
    RecordVector records, spare(scene.triangles.size());
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        const glm::vec3 lower = glm::min(t.v0, glm::min(t.v1, t.v2));
        const glm::vec3 upper = glm::max(t.v0, glm::max(t.v1, t.v2));
        records.push_back({lower, static_cast<uint32_t>(i), upper, 0.0f});
    }
    BuildContext context;
    context.leafAtMost = leafAtMost;
    const SubtreeBuilder builder(BvhBuildOptions{}, context);
    BuildTask root;
    root.first = records.data();
    root.spare = spare.data();
    root.count = static_cast<uint32_t>(records.size());
    root.bounds = boundsOf(records.data(), records.data() + records.size());
    Subtree tree;
    tree.nodes.resize(1);
    builder.buildSubtree(tree, root);
    return tree;
}

TEST(BvhLeafMerge, NoNodeOfAtMostKLeafMergeReferencesIsSplit) {
    const Scene scene = makeTriangleSoup(5000, 0.05f, 21);
    const Subtree merged = buildWithLeafAtMost(scene, kLeafMerge);
    const Subtree split = buildWithLeafAtMost(scene, 0);
    const std::vector<uint32_t> mergedUnder = referencesUnder(merged);
    const std::vector<uint32_t> splitUnder = referencesUnder(split);
    ASSERT_EQ(mergedUnder[0], 5000u);
    ASSERT_EQ(splitUnder[0], 5000u);
    int largeLeaves = 0; // leaves of more than maxLeafSize (4) references
    for (std::size_t i = 0; i < merged.nodes.size(); ++i) {
        if (merged.nodes[i].isLeaf()) {
            EXPECT_LE(merged.nodes[i].count, kLeafMerge);
            largeLeaves += merged.nodes[i].count > 4 ? 1 : 0;
        } else {
            EXPECT_GT(mergedUnder[i], kLeafMerge) << i;
        }
    }
    EXPECT_GT(largeLeaves, 100);
    // Without the rule, nodes of 5 to 8 references must split (maxLeafSize 4).
    int smallInner = 0;
    for (std::size_t i = 0; i < split.nodes.size(); ++i) {
        EXPECT_LE(split.nodes[i].count, 4u);
        smallInner += !split.nodes[i].isLeaf() && splitUnder[i] <= kLeafMerge ? 1 : 0;
    }
    EXPECT_GT(smallInner, 100);
    EXPECT_LT(merged.nodes.size(), split.nodes.size());
}

// Leaves share blocks (bvh_collapse.cpp), packed by their sizes, so both trees place every
// leaf at the same blocks; where a leaf of two blocks divides its triangles between them depends
// on their order in the leaf, which the rule changes. The scene triangles of a wide leaf's
// blocks, each once, with the other block of any leaf of two that shares one of them.
std::vector<uint32_t> pairedBlocks(const Bvh& bvh) {
    std::vector<uint32_t> pairedWith(bvh.triangleBlocks.size(), kWideEmpty);
    for (const BvhWideNode& node : bvh.wideNodes) {
        for (uint32_t c : node.child) {
            if (c != kWideEmpty && (c & kWideLeafFlag) != 0 && (c >> kWideBlockShift & 7u) == 1u) {
                const uint32_t first = c & kWideFirstBlockMask;
                pairedWith[first] = first + 1;
                pairedWith[first + 1] = first;
            }
        }
    }
    return pairedWith;
}

std::set<uint32_t> leafTriangles(const Bvh& bvh, const std::vector<uint32_t>& pairedWith,
                                 uint32_t child) {
    const uint32_t first = child & kWideFirstBlockMask;
    const uint32_t blocks = ((child & ~kWideLeafFlag) >> kWideBlockShift) + 1;
    std::set<uint32_t> triangles;
    auto add = [&](uint32_t b) {
        triangles.insert(std::begin(bvh.triangleBlocks[b].sceneIndex),
                         std::end(bvh.triangleBlocks[b].sceneIndex));
    };
    for (uint32_t b = first; b < first + blocks; ++b) {
        add(b);
        if (pairedWith[b] != kWideEmpty) {
            add(pairedWith[b]);
        }
    }
    return triangles;
}

// The wide tree built with the rule (binary nodes dropped) against the one built without it
// (binary nodes kept): the same nodes, boxes and children, the same triangles in each leaf.
void expectSameWideTree(const Scene& scene, BvhBuildOptions options) {
    options.keepBinaryNodes = false;
    const Bvh merged = buildBvh(scene, options);
    options.keepBinaryNodes = true;
    const Bvh split = buildBvh(scene, options);
    ASSERT_FALSE(merged.wideNodes.empty());
    ASSERT_EQ(merged.wideNodes.size(), split.wideNodes.size());
    EXPECT_LE(merged.leafReferences, split.leafReferences);
    EXPECT_LE(merged.triangleBlocks.size(), split.triangleBlocks.size());
    const std::vector<uint32_t> mergedPairs = pairedBlocks(merged);
    const std::vector<uint32_t> splitPairs = pairedBlocks(split);
    int leaves = 0;
    for (std::size_t i = 0; i < merged.wideNodes.size(); ++i) {
        const BvhWideNode &x = merged.wideNodes[i], &y = split.wideNodes[i];
        ASSERT_EQ(std::memcmp(x.lower, y.lower, sizeof(x.lower)), 0) << i;
        ASSERT_EQ(std::memcmp(x.upper, y.upper, sizeof(x.upper)), 0) << i;
        for (int c = 0; c < kWideLanes; ++c) {
            const bool leaf = x.child[c] != kWideEmpty && (x.child[c] & kWideLeafFlag) != 0;
            if (!leaf) {
                ASSERT_EQ(x.child[c], y.child[c]) << i << " " << c;
                continue;
            }
            ASSERT_EQ(x.child[c], y.child[c]) << i << " " << c;
            ASSERT_EQ(leafTriangles(merged, mergedPairs, x.child[c]),
                      leafTriangles(split, splitPairs, y.child[c]))
                << i << " " << c;
            ++leaves;
        }
    }
    EXPECT_GT(leaves, 0);
}

// Large quads across small triangles: pre-splits, and spatial splits when they are allowed.
Scene makeCluttered(uint32_t seed) {
    Scene scene = makeTriangleSoup(20000, 0.03f, seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 a{unit(rng), unit(rng), unit(rng)};
        scene.triangles.push_back({a, {-a.x, unit(rng), -a.z}, {unit(rng), -a.y, unit(rng)}, 0});
    }
    return scene;
}

TEST(BvhLeafMerge, SameWideTreeAsWhenTheBinaryNodesAreKept) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "no 8-wide form on this CPU";
    }
    // With spatial splits and without: nodes of fewer than kMinSpatialCount references try none
    // (bvh_build_subtree.cpp), so the nodes of at most kLeafMerge references that become leaves
    // unsplit would not have made spatial splits either.
    BvhBuildOptions noSpatial;
    noSpatial.spatialSplitBudget = 0.0f;
    expectSameWideTree(makeTriangleSoup(20000, 0.03f, 22), noSpatial);
    const Scene cluttered = makeCluttered(23);
    expectSameWideTree(cluttered, noSpatial);
    noSpatial.threads = 2;
    expectSameWideTree(cluttered, noSpatial);
    BvhBuildOptions spatial; // the defaults
    expectSameWideTree(cluttered, spatial);
    spatial.threads = 2;
    expectSameWideTree(cluttered, spatial);
}

TEST(BvhLeafMerge, SpatialSplitsOnlyAboveTheLeavesMadeUnsplit) {
    const Scene scene = makeCluttered(27);
    BvhBuildOptions options;
    const Bvh merged = buildBvh(scene, options);
    options.keepBinaryNodes = true;
    const Bvh split = buildBvh(scene, options);
    EXPECT_GT(split.leafReferences, scene.triangles.size()); // spatial splits were made
    EXPECT_EQ(merged.leafReferences, split.leafReferences);
    EXPECT_GT(expectMatchesBruteForce(scene, merged, makeRandomRays(1000, 28)), 100);
}

TEST(BvhLeafMerge, UnsplitLeavesMatchBruteForce) {
    const Scene scene = makeTriangleSoup(8000, 0.05f, 24);
    const Bvh bvh = buildBvh(scene);
    EXPECT_GT(expectMatchesBruteForce(scene, bvh, makeRandomRays(1000, 25)), 100);
    expectMatchesBruteForce(scene, bvh, makeAxisAlignedRays(300, 1.5f, 26));
}

// The spans the collapse reads (bvh_collapse.h): filled range by range, as the build fills them
// (each subtree's nodes on its own thread, then the top's), each node's leaf triangles are its
// leaves' together, and a node opens into its children only when it holds more than kLeafMerge
// triangles and so does one of its children.
TEST(BvhLeafMerge, SpansOfBinaryNodesFilledRangeByRange) {
    static_assert(kLeafMerge == 8, "the counts below are chosen around 8");
    auto inner = [](uint32_t firstChild) {
        BvhNode n;
        n.index = firstChild;
        n.count = 0;
        return n;
    };
    auto leaf = [](uint32_t first, uint32_t count) {
        BvhNode n;
        n.index = first;
        n.count = count;
        return n;
    };
    // 0 -> (1, 2); 2 -> (3, 4); 3 -> (5, 6); the leaves hold 4 + 6 + 5 + 7 = 22 triangles.
    const std::vector<BvhNode> nodes = {inner(1),    leaf(0, 4), inner(3),  inner(5),
                                        leaf(16, 6), leaf(4, 5), leaf(9, 7)};
    std::vector<LeafSpan> spans(nodes.size());
    spanBinaryNodes(nodes.data(), 3, nodes.size(), spans.data()); // a subtree's nodes first
    spanBinaryNodes(nodes.data(), 0, 3, spans.data());            // then those above them
    const struct {
        uint32_t first, count;
        bool opens;
    } expected[] = {{0, 22, true},  {0, 4, false}, {4, 18, true}, {4, 12, false},
                    {16, 6, false}, {4, 5, false}, {9, 7, false}};
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        EXPECT_EQ(spans[i].first, expected[i].first) << "node " << i;
        EXPECT_EQ(spans[i].count, expected[i].count) << "node " << i;
        EXPECT_EQ(spans[i].opens, expected[i].opens) << "node " << i;
    }
}

} // namespace
} // namespace raylab::accel_test
