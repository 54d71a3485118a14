// Binary to 8-wide BVH. Each wide node starts from a binary node's two children and keeps
// opening the child with the largest surface area until it has 8 children or none can open.
// A binary subtree with at most kLeafMerge triangles becomes one leaf: one 8-lane triangle
// test costs about as much as a 4-lane one, and it saves the box tests below it.

#include "bvh_collapse.h"

#include <algorithm>
#include <vector>

namespace raylab {

namespace {

constexpr uint32_t kLeafMerge = 8;

struct Range {
    uint32_t first = 0, count = 0; // the subtree's triangles [first, first + count)
};

float area(const BvhNode& n) { return Aabb{n.lower, n.upper}.area(); }

class Collapser {
public:
    explicit Collapser(Bvh& bvh)
        : bvh_(bvh), ranges_(bvh.nodes.size()), slotOf_(bvh.triangles.size(), 0) {
        // Children always follow their parent, so a backwards pass sees children first.
        for (std::size_t i = bvh.nodes.size(); i-- > 0;) {
            const BvhNode& n = bvh.nodes[i];
            if (n.isLeaf()) {
                ranges_[i] = {n.index, n.count};
            } else {
                ranges_[i] = {ranges_[n.index].first,
                              ranges_[n.index].count + ranges_[n.index + 1].count};
            }
        }
    }

    // Builds every wide node; returns the depth of the wide tree.
    int run() {
        bvh_.wideNodes.reserve(bvh_.nodes.size() / 4 + 1);
        bvh_.wideNodes.emplace_back();
        int deepest = 0;
        std::vector<Pending> stack{{0, 0, 1}};
        while (!stack.empty()) {
            const Pending p = stack.back();
            stack.pop_back();
            deepest = std::max(deepest, p.depth);
            fill(p, stack);
        }
        return deepest;
    }

private:
    struct Pending {
        uint32_t binary; // binary node the wide node stands for
        uint32_t wide;   // its slot in wideNodes
        int depth;
    };

    bool opens(uint32_t binary) const {
        return !bvh_.nodes[binary].isLeaf() && ranges_[binary].count > kLeafMerge;
    }

    void fill(const Pending& p, std::vector<Pending>& stack) {
        std::vector<uint32_t> slots;
        if (opens(p.binary)) {
            slots = {bvh_.nodes[p.binary].index, bvh_.nodes[p.binary].index + 1};
        } else {
            slots = {p.binary};
        }
        while (slots.size() < static_cast<std::size_t>(kWideLanes)) {
            int best = -1;
            for (std::size_t s = 0; s < slots.size(); ++s) {
                if (opens(slots[s]) &&
                    (best < 0 || area(bvh_.nodes[slots[s]]) > area(bvh_.nodes[slots[best]]))) {
                    best = static_cast<int>(s);
                }
            }
            if (best < 0) {
                break;
            }
            const uint32_t opened = slots[best];
            slots[best] = bvh_.nodes[opened].index;
            slots.push_back(bvh_.nodes[opened].index + 1);
        }

        BvhWideNode node;
        for (int c = 0; c < kWideLanes; ++c) {
            for (int a = 0; a < 3; ++a) {
                node.lower[a][c] = kInfinity;
                node.upper[a][c] = -kInfinity;
            }
            node.child[c] = kWideEmpty;
        }
        for (std::size_t s = 0; s < slots.size(); ++s) {
            const BvhNode& b = bvh_.nodes[slots[s]];
            for (int a = 0; a < 3; ++a) {
                node.lower[a][s] = b.lower[a];
                node.upper[a][s] = b.upper[a];
            }
            if (opens(slots[s])) {
                const auto wide = static_cast<uint32_t>(bvh_.wideNodes.size());
                bvh_.wideNodes.emplace_back();
                node.child[s] = wide;
                stack.push_back({slots[s], wide, p.depth + 1});
            } else {
                const auto first = static_cast<uint32_t>(bvh_.triangleBlocks.size());
                const uint32_t blocks = addBlocks(ranges_[slots[s]]);
                if (blocks > kWideMaxLeafBlocks || first + blocks > kWideFirstBlockMask) {
                    overflow_ = true;
                    continue;
                }
                node.child[s] = kWideLeafFlag | (blocks - 1) << kWideBlockShift | first;
            }
        }
        bvh_.wideNodes[p.wide] = node;
    }

    // Appends the blocks of a leaf; spare lanes repeat the block's first triangle.
    uint32_t addBlocks(const Range& r) {
        uint32_t blocks = 0;
        for (uint32_t first = r.first; first < r.first + r.count; first += kWideLanes) {
            BvhTriangleBlock block;
            for (int lane = 0; lane < kWideLanes; ++lane) {
                const uint32_t i = first + static_cast<uint32_t>(lane) < r.first + r.count
                                       ? first + static_cast<uint32_t>(lane)
                                       : first;
                const BvhTriangle& t = bvh_.triangles[i];
                const glm::vec3* v[3] = {&t.v0, &t.v1, &t.v2};
                for (int k = 0; k < 3; ++k) {
                    for (int a = 0; a < 3; ++a) {
                        block.vertex[k][a][lane] = (*v[k])[a];
                    }
                }
                block.sceneIndex[lane] = t.sceneIndex;
                if (i == first + static_cast<uint32_t>(lane)) {
                    slotOf_[i] = static_cast<uint32_t>(bvh_.triangleBlocks.size()) * kWideLanes +
                                 static_cast<uint32_t>(lane);
                }
            }
            bvh_.triangleBlocks.push_back(block);
            ++blocks;
        }
        return blocks;
    }

    Bvh& bvh_;
    std::vector<Range> ranges_;
    std::vector<uint32_t> slotOf_; // leaf triangle index -> its lane in triangleBlocks
    bool overflow_ = false;        // a leaf or the block count does not fit a child reference

public:
    bool overflowed() const { return overflow_; }

    // Points the binary leaves at the blocks' lanes and drops the binary triangle copies. A
    // binary leaf lies inside one wide leaf, whose blocks hold its triangles in leaf order with
    // padding only after the last one, so its triangles stay contiguous slots.
    void shareTriangles() {
        for (BvhNode& node : bvh_.nodes) {
            if (node.isLeaf()) {
                node.index = slotOf_[node.index];
            }
        }
        bvh_.triangles.clear();
        bvh_.triangles.shrink_to_fit();
    }
};

} // namespace

void buildWideBvh(Bvh& bvh) {
    bvh.wideNodes.clear();
    bvh.triangleBlocks.clear();
    if (bvh.nodes.empty()) {
        return;
    }
    Collapser collapser(bvh);
    const int depth = collapser.run();
    if (collapser.overflowed() || (kWideLanes - 1) * depth + 1 > kWideStackSize) {
        bvh.wideNodes.clear();
        bvh.triangleBlocks.clear();
    } else {
        collapser.shareTriangles();
    }
    bvh.wideNodes.shrink_to_fit();
    bvh.triangleBlocks.shrink_to_fit();
}

} // namespace raylab
