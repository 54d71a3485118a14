// Binary to 8-wide BVH. Each wide node starts from a binary node's two children and keeps
// opening the child with the largest surface area until it has 8 children or none can open.
// A binary subtree with at most kLeafMerge triangles becomes one leaf: one 8-lane triangle
// test costs about as much as a 4-lane one, and it saves the box tests below it. A subtree whose
// two children are such leaves becomes one leaf of two blocks: it saves the wide node that would
// hold just those two (a third of the dragon's wide nodes did) and packs the blocks fuller, and
// measured no slower (PERFORMANCE.md, "BVH memory").
//
// The top of the wide tree is made first, down to binary subtrees of at most a number of
// triangles that depends only on the tree; those become wide subtrees, made in parallel, their
// nodes into their own arrays appended in a fixed order (top first, then each subtree's), their
// blocks straight into the BVH's array at offsets known from the binary tree in the same order,
// so the result is the same whatever the thread count.

#include "bvh/build/bvh_collapse.h"

#include "huge_pages.h"

#include <algorithm>
#include <vector>

namespace raylab {

namespace {

constexpr uint32_t kMinPartTriangles = 2048; // smallest wide subtree made as a parallel task

struct Range {
    uint32_t first = 0, count = 0; // the subtree's triangles [first, first + count)
};

float area(const BvhNode& n) { return Aabb{n.lower, n.upper}.area(); }

// A wide subtree waiting to be made: the binary node it stands for, and where it hangs.
struct PendingPart {
    uint32_t binary = 0;
    uint32_t parent = 0; // wide node (of the top) whose child it is
    int lane = 0;
    int depth = 0; // of its root in the whole wide tree
};

// A part of the wide tree: its nodes in its own array (inner children index them), its blocks
// in the BVH's from `firstBlock` on (leaves index them there).
struct WidePart {
    std::vector<BvhWideNode> nodes; // nodes[0] is its root
    BvhTriangleBlock* blocks = nullptr;
    uint32_t firstBlock = 0;
    uint32_t blockCount = 0;
    int depth = 0;         // deepest level reached, counted in the whole tree
    bool overflow = false; // a leaf or the block count does not fit a child reference
};

// What collapsing needs from the binary tree; shared read-only by the threads, except slotOf,
// of which each part writes only its own triangles' entries.
struct BinaryTree {
    const Bvh& bvh;
    const Scene& scene;
    const std::vector<uint32_t>& leafScene; // leaf triangle -> scene triangle
    std::vector<Range> ranges;              // per binary node
    std::vector<uint32_t> slotOf;           // leaf triangle -> its lane in the BVH's blocks
    std::vector<bool> leaf;                 // per binary node: it becomes one wide leaf
    std::vector<uint32_t> blocksUnder;      // per binary node: the blocks of its wide subtree

    BinaryTree(const Bvh& b, const Scene& s, const std::vector<uint32_t>& leaves)
        : bvh(b), scene(s), leafScene(leaves), ranges(b.nodes.size()), slotOf(leaves.size()),
          leaf(b.nodes.size()), blocksUnder(b.nodes.size()) {
        // Children always follow their parent, so a backwards pass sees children first.
        for (std::size_t i = b.nodes.size(); i-- > 0;) {
            const BvhNode& n = b.nodes[i];
            if (n.isLeaf()) {
                ranges[i] = {n.index, n.count};
                leaf[i] = true;
            } else {
                const uint32_t l = n.index, r = n.index + 1;
                ranges[i] = {ranges[l].first, ranges[l].count + ranges[r].count};
                leaf[i] = ranges[i].count <= kLeafMerge ||
                          (ranges[l].count <= kLeafMerge && ranges[r].count <= kLeafMerge);
                blocksUnder[i] = blocksUnder[l] + blocksUnder[r];
            }
            if (leaf[i]) { // a wide leaf of addBlocks
                blocksUnder[i] = (ranges[i].count + kWideLanes - 1) / kWideLanes;
            }
        }
    }

    bool opens(uint32_t binary) const { return !leaf[binary]; }
};

class Collapser {
public:
    // Makes the wide subtree of binary node `binary` (whose root is at depth `depth`) into
    // part. With deferBelow > 0, children that open and hold at most deferBelow triangles
    // are left to `deferred` instead (their child references are set later).
    Collapser(BinaryTree& tree, WidePart& part, uint32_t deferBelow,
              std::vector<PendingPart>* deferred)
        : tree_(tree), part_(part), deferBelow_(deferBelow), deferred_(deferred) {}

    void run(uint32_t binary, int depth) {
        part_.nodes.emplace_back();
        std::vector<Pending> stack{{binary, 0, depth}};
        while (!stack.empty()) {
            const Pending p = stack.back();
            stack.pop_back();
            part_.depth = std::max(part_.depth, p.depth);
            fill(p, stack);
        }
    }

private:
    struct Pending {
        uint32_t binary; // binary node the wide node stands for
        uint32_t wide;   // its slot in part_.nodes
        int depth;
    };

    const BvhNode& node(uint32_t binary) const { return tree_.bvh.nodes[binary]; }

    void fill(const Pending& p, std::vector<Pending>& stack) {
        uint32_t slots[kWideLanes];
        float areas[kWideLanes]; // of slots that can open; -1 for the others
        int count = 0;
        auto areaIfOpens = [&](uint32_t binary) {
            return tree_.opens(binary) ? area(node(binary)) : -1.0f;
        };
        auto add = [&](uint32_t binary) {
            slots[count] = binary;
            areas[count] = areaIfOpens(binary);
            ++count;
        };
        if (tree_.opens(p.binary)) {
            add(node(p.binary).index);
            add(node(p.binary).index + 1);
        } else {
            add(p.binary);
        }
        while (count < kWideLanes) {
            int best = -1;
            for (int s = 0; s < count; ++s) {
                if (areas[s] >= 0.0f && (best < 0 || areas[s] > areas[best])) {
                    best = s;
                }
            }
            if (best < 0) {
                break;
            }
            // The opened node's left child takes its slot, its right child the next free one.
            const uint32_t opened = slots[best];
            slots[best] = node(opened).index;
            areas[best] = areaIfOpens(slots[best]);
            add(node(opened).index + 1);
        }

        BvhWideNode wide{};
        for (int c = 0; c < kWideLanes; ++c) {
            for (int a = 0; a < 3; ++a) {
                wide.lower[a][c] = kInfinity;
                wide.upper[a][c] = -kInfinity;
            }
            wide.child[c] = kWideEmpty;
        }
        for (int s = 0; s < count; ++s) {
            const BvhNode& b = node(slots[s]);
            for (int a = 0; a < 3; ++a) {
                wide.lower[a][s] = b.lower[a];
                wide.upper[a][s] = b.upper[a];
            }
            if (tree_.opens(slots[s])) {
                if (deferBelow_ > 0 && tree_.ranges[slots[s]].count <= deferBelow_) {
                    deferred_->push_back({slots[s], p.wide, s, p.depth + 1});
                    continue;
                }
                const auto child = static_cast<uint32_t>(part_.nodes.size());
                part_.nodes.emplace_back();
                wide.child[s] = child;
                stack.push_back({slots[s], child, p.depth + 1});
            } else {
                const uint32_t first = part_.firstBlock + part_.blockCount;
                const uint32_t blocks = addBlocks(tree_.ranges[slots[s]]);
                if (blocks > kWideMaxLeafBlocks || first + blocks > kWideFirstBlockMask) {
                    part_.overflow = true;
                    continue;
                }
                wide.child[s] = kWideLeafFlag | (blocks - 1) << kWideBlockShift | first;
            }
        }
        part_.nodes[p.wide] = wide;
    }

    // Appends the blocks of a leaf; spare lanes repeat the block's first triangle.
    uint32_t addBlocks(const Range& r) {
        uint32_t blocks = 0;
        for (uint32_t first = r.first; first < r.first + r.count; first += kWideLanes) {
            const uint32_t at = part_.firstBlock + part_.blockCount;
            BvhTriangleBlock& block = part_.blocks[at];
            for (int lane = 0; lane < kWideLanes; ++lane) {
                const uint32_t i = first + static_cast<uint32_t>(lane) < r.first + r.count
                                       ? first + static_cast<uint32_t>(lane)
                                       : first;
                const Triangle& t = tree_.scene.triangles[tree_.leafScene[i]];
                const glm::vec3* v[3] = {&t.v0, &t.v1, &t.v2};
                for (int k = 0; k < 3; ++k) {
                    for (int a = 0; a < 3; ++a) {
                        block.vertex[k][a][lane] = (*v[k])[a];
                    }
                }
                block.sceneIndex[lane] = tree_.leafScene[i];
                if (i == first + static_cast<uint32_t>(lane)) {
                    tree_.slotOf[i] = at * kWideLanes + static_cast<uint32_t>(lane);
                }
            }
            ++part_.blockCount;
            ++blocks;
        }
        return blocks;
    }

    BinaryTree& tree_;
    WidePart& part_;
    uint32_t deferBelow_;
    std::vector<PendingPart>* deferred_;
};

// Moves a part's inner child references by its offset in the whole node array (its leaves
// already index the whole block array).
void relocate(WidePart& part, uint32_t nodeOffset) {
    for (BvhWideNode& n : part.nodes) {
        for (uint32_t& c : n.child) {
            if (c != kWideEmpty && (c & kWideLeafFlag) == 0) {
                c += nodeOffset;
            }
        }
    }
}

} // namespace

bool buildWideBvh(Bvh& bvh, const Scene& scene, const std::vector<uint32_t>& leafScene,
                  BuildTeam& team) {
    bvh.wideNodes.clear();
    bvh.triangleBlocks.clear();
    if (bvh.nodes.empty()) {
        return false;
    }
    BinaryTree tree(bvh, scene, leafScene);
    const uint32_t totalBlocks = tree.blocksUnder[0];
    if (totalBlocks > kWideFirstBlockMask) {
        return false;
    }
    // Every block is written below (value-initialised first by resize): allocated, advised huge
    // pages (huge_pages.h), then first touched.
    bvh.triangleBlocks.reserve(totalBlocks);
    adviseHugePages(bvh.triangleBlocks.data(), totalBlocks * sizeof(BvhTriangleBlock));
    bvh.triangleBlocks.resize(totalBlocks);
    WidePart top;
    top.blocks = bvh.triangleBlocks.data();
    std::vector<PendingPart> pending;
    const uint32_t deferBelow =
        std::max(kMinPartTriangles, static_cast<uint32_t>(leafScene.size() / 128));
    Collapser(tree, top, deferBelow, &pending).run(0, 1);

    // Each part's blocks follow the top's and the parts' before it.
    std::vector<WidePart> parts(pending.size());
    uint32_t blockAt = top.blockCount;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        parts[i].blocks = bvh.triangleBlocks.data();
        parts[i].firstBlock = blockAt;
        blockAt += tree.blocksUnder[pending[i].binary];
    }
    team.forEach(parts.size(), [&](std::size_t i) {
        parts[i].depth = pending[i].depth;
        Collapser(tree, parts[i], 0, nullptr).run(pending[i].binary, pending[i].depth);
    });

    // Offsets, then every part's nodes in place.
    std::vector<uint32_t> nodeAt(parts.size());
    std::size_t nodes = top.nodes.size();
    int depth = top.depth;
    bool overflow = top.overflow;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        nodeAt[i] = static_cast<uint32_t>(nodes);
        nodes += parts[i].nodes.size();
        depth = std::max(depth, parts[i].depth);
        overflow = overflow || parts[i].overflow;
        top.nodes[pending[i].parent].child[pending[i].lane] = nodeAt[i];
    }
    if (overflow || (kWideLanes - 1) * depth + 1 > kWideStackSize) {
        std::vector<BvhTriangleBlock>().swap(bvh.triangleBlocks);
        return false;
    }
    // Allocated, advised huge pages, then first touched (huge_pages.h).
    bvh.wideNodes.reserve(nodes);
    adviseHugePages(bvh.wideNodes.data(), nodes * sizeof(BvhWideNode));
    bvh.wideNodes.resize(nodes);
    std::copy(top.nodes.begin(), top.nodes.end(), bvh.wideNodes.begin());
    team.forEach(parts.size(), [&](std::size_t i) {
        relocate(parts[i], nodeAt[i]);
        std::copy(parts[i].nodes.begin(), parts[i].nodes.end(), bvh.wideNodes.begin() + nodeAt[i]);
        parts[i] = WidePart{};
    });

    // Points the binary leaves at the blocks' lanes. A binary leaf lies inside one wide leaf,
    // whose blocks hold its triangles in leaf order with padding only after the last one, so
    // its triangles stay contiguous slots.
    for (BvhNode& node : bvh.nodes) {
        if (node.isLeaf()) {
            node.index = tree.slotOf[node.index];
        }
    }
    return true;
}

} // namespace raylab
