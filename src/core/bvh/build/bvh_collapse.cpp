// Binary to 8-wide BVH. Each wide node starts from a binary node's two children and keeps
// opening the child with the largest surface area until it has 8 children or none can open.
// A binary subtree with at most kLeafMerge triangles becomes one leaf: one 8-lane triangle
// test costs about as much as a 4-lane one, and it saves the box tests below it. A subtree whose
// two children are such leaves becomes one leaf of two blocks: it saves the wide node that would
// hold just those two (a third of the dragon's wide nodes did) and measured no slower
// (PERFORMANCE.md, "What each change gained: memory").
//
// Leaves share blocks: each leaf's triangles take consecutive lanes of one block (a leaf of more
// than 8, of two), the leaves of a part packed best fit, largest first. A ray that tests a
// leaf's block tests the other leaves' lanes too; those are real triangles of the scene, and the
// closest-hit rule (nearest t, then lowest scene index) is a property of the set of triangles
// hit, so testing more of them never changes an answer. Lanes no leaf takes repeat the block's
// first triangle (bvh_wide.h).
//
// The top of the wide tree is made first, down to binary subtrees of at most a number of
// triangles that depends only on the tree; those become wide subtrees, made in parallel, their
// nodes and their blocks counted in their own part; the parts are then placed in a fixed order
// (top first, then each subtree's) and their blocks written in parallel, so the result is the
// same whatever the thread count.

#include "bvh/build/bvh_collapse.h"

#include "bvh/build/bvh_slot_array.h"

#include <algorithm>
#include <vector>

namespace raylab {

namespace {

constexpr uint32_t kMinPartTriangles = 2048; // smallest wide subtree made as a parallel task

float area(const BvhNode& n) { return Aabb{n.lower, n.upper}.area(); }

// A wide subtree waiting to be made: the binary node it stands for, and where it hangs.
struct PendingPart {
    uint32_t binary = 0;
    uint32_t parent = 0; // wide node (of the top) whose child it is
    int lane = 0;
    int depth = 0; // of its root in the whole wide tree
};

// A part of the wide tree: its nodes in its own array (inner children index them) and its
// blocks, counted in the part (leaves index them there) until the part is placed at firstBlock
// of the BVH's array.
struct WidePart {
    SlotArray<BvhWideNode> nodes; // nodes[0] is its root
    SlotArray<LeafPlacement> leaves;
    std::vector<uint8_t> lanesUsed; // per block of the part: lanes [0, lanesUsed) hold leaves
    uint32_t firstBlock = 0;
    int depth = 0;         // deepest level reached, counted in the whole tree
    bool overflow = false; // a leaf does not fit a child reference
};

// What collapsing needs from the binary tree; shared read-only by the threads, except slotOf,
// of which each part writes only its own triangles' entries.
struct BinaryTree {
    const Bvh& bvh;
    const Scene& scene;
    const UninitialisedVector<uint32_t>& leafScene; // leaf triangle -> scene triangle
    const UninitialisedVector<LeafSpan>& spans;     // per binary node
    // Leaf triangle -> its lane in the BVH's blocks; empty when the binary leaves are not to
    // be pointed at the blocks.
    std::vector<uint32_t> slotOf;

    BinaryTree(const Bvh& b, const Scene& s, const UninitialisedVector<uint32_t>& leaves,
               const UninitialisedVector<LeafSpan>& nodeSpans, bool slots)
        : bvh(b), scene(s), leafScene(leaves), spans(nodeSpans), slotOf(slots ? leaves.size() : 0) {
    }

    bool opens(uint32_t binary) const { return spans[binary].opens; }
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
        part_.nodes.resize(1); // written by fill(), as every node
        std::vector<Pending> stack{{binary, 0, depth}};
        while (!stack.empty()) {
            const Pending p = stack.back();
            stack.pop_back();
            part_.depth = std::max(part_.depth, p.depth);
            fill(p, stack);
        }
        packLeaves();
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
        // Slots to spare: leaves of two blocks (two binary leaves of up to 8 merged) are split,
        // largest first, into their halves, each a leaf of one block. A ray then tests only the
        // halves whose boxes it enters, and the halves pack into blocks with other leaves.
        auto splits = [&](uint32_t binary) {
            return !tree_.opens(binary) && !node(binary).isLeaf() &&
                   tree_.spans[binary].count > kLeafMerge;
        };
        while (count < kWideLanes) {
            int best = -1;
            for (int s = 0; s < count; ++s) {
                if (splits(slots[s]) &&
                    (best < 0 || area(node(slots[s])) > area(node(slots[best])))) {
                    best = s;
                }
            }
            if (best < 0) {
                break;
            }
            const uint32_t split = slots[best];
            slots[best] = node(split).index;
            areas[best] = -1.0f;
            add(node(split).index + 1);
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
            if (!tree_.opens(slots[s])) {
                part_.leaves.push_back({tree_.spans[slots[s]], p.wide, static_cast<uint32_t>(s)});
                continue;
            }
            if (deferBelow_ > 0 && tree_.spans[slots[s]].count <= deferBelow_) {
                deferred_->push_back({slots[s], p.wide, s, p.depth + 1});
                continue;
            }
            const auto child = static_cast<uint32_t>(part_.nodes.size());
            part_.nodes.resize(child + std::size_t{1});
            wide.child[s] = child;
            stack.push_back({slots[s], child, p.depth + 1});
        }
        part_.nodes[p.wide] = wide;
    }

    // Places the part's leaves in its blocks, largest first (in the order made on equal sizes):
    // a leaf of one block in the block with the least room that takes it (the latest made of
    // those), a longer one in new blocks; points their child references at the part's blocks.
    void packLeaves() {
        std::stable_sort(part_.leaves.begin(), part_.leaves.end(),
                         [](const LeafPlacement& a, const LeafPlacement& b) {
                             return a.triangles.count > b.triangles.count;
                         });
        std::vector<uint32_t> withRoom[kWideLanes]; // [n]: blocks with n free lanes
        for (LeafPlacement& leaf : part_.leaves) {
            const uint32_t count = leaf.triangles.count;
            const uint32_t blocks = (count + kWideLanes - 1) / kWideLanes;
            if (blocks == 0 || blocks > kWideMaxLeafBlocks) { // no child reference holds it
                part_.overflow = true;
                continue;
            }
            auto block = static_cast<uint32_t>(part_.lanesUsed.size());
            for (uint32_t room = count; blocks == 1 && room < kWideLanes; ++room) {
                if (!withRoom[room].empty()) {
                    block = withRoom[room].back();
                    withRoom[room].pop_back();
                    break;
                }
            }
            if (block == part_.lanesUsed.size()) {
                part_.lanesUsed.resize(block + blocks, 0);
            }
            const uint32_t last = block + blocks - 1;
            leaf.block = block;
            leaf.lane = part_.lanesUsed[block];
            for (uint32_t b = block; b < last; ++b) {
                part_.lanesUsed[b] = kWideLanes;
            }
            part_.lanesUsed[last] =
                static_cast<uint8_t>(leaf.lane + count - (blocks - 1) * kWideLanes);
            if (part_.lanesUsed[last] < kWideLanes) {
                withRoom[kWideLanes - part_.lanesUsed[last]].push_back(last);
            }
            part_.nodes[leaf.node].child[leaf.slot] =
                kWideLeafFlag | (blocks - 1) << kWideBlockShift | block;
        }
    }

    BinaryTree& tree_;
    WidePart& part_;
    uint32_t deferBelow_;
    std::vector<PendingPart>* deferred_;
};

// Moves a part's child references by its offsets in the whole arrays: inner children by
// nodeOffset, leaves by the part's first block.
void relocate(WidePart& part, uint32_t nodeOffset) {
    for (BvhWideNode& n : part.nodes) {
        for (uint32_t& c : n.child) {
            if (c == kWideEmpty) {
                continue;
            }
            c += (c & kWideLeafFlag) != 0 ? part.firstBlock : nodeOffset;
        }
    }
}

// Writes a placed part's leaves into its blocks of `blocks` (the BVH's array), their spare
// lanes, and the lanes of its leaf triangles into tree.slotOf (unless that is empty).
void writeBlocks(const WidePart& part, BinaryTree& tree, BvhTriangleBlock* blocks) {
    for (const LeafPlacement& leaf : part.leaves) {
        const uint32_t firstSlot = (part.firstBlock + leaf.block) * kWideLanes + leaf.lane;
        for (uint32_t j = 0; j < leaf.triangles.count; ++j) {
            const uint32_t i = leaf.triangles.first + j;
            const uint32_t slot = firstSlot + j;
            BvhTriangleBlock& block = blocks[slot / kWideLanes];
            const uint32_t lane = slot % kWideLanes;
            const Triangle& t = tree.scene.triangles[tree.leafScene[i]];
            const glm::vec3* v[3] = {&t.v0, &t.v1, &t.v2};
            for (int k = 0; k < 3; ++k) {
                for (int a = 0; a < 3; ++a) {
                    block.vertex[k][a][lane] = (*v[k])[a];
                }
            }
            block.sceneIndex[lane] = tree.leafScene[i];
            if (!tree.slotOf.empty()) {
                tree.slotOf[i] = slot;
            }
        }
    }
    for (std::size_t b = 0; b < part.lanesUsed.size(); ++b) {
        BvhTriangleBlock& block = blocks[part.firstBlock + b];
        for (uint32_t lane = part.lanesUsed[b]; lane < kWideLanes; ++lane) {
            for (int k = 0; k < 3; ++k) {
                for (int a = 0; a < 3; ++a) {
                    block.vertex[k][a][lane] = block.vertex[k][a][0];
                }
            }
            block.sceneIndex[lane] = block.sceneIndex[0];
        }
    }
}

// Where each wide subtree's arrays go in the two arrays they share (CollapseMemory): part i's
// nodes in slot i of one, its leaves in slot i of the other. Sized for n leaf references: a
// sixteenth of them and 16 more nodes, a quarter and 16 more leaves. Measured per part on the
// meshes of PERFORMANCE.md: 0.033-0.036 nodes and 0.14-0.16 leaves a reference over all parts,
// 0.048-0.071 and 0.18-0.29 at most in one (a small part of Sponza's). Larger slots would cost:
// every page of the shared arrays is faulted in, used or not. A part that needs more moves its
// array out of its slot (SlotArray).
struct PartSlots {
    SlotLayout<BvhWideNode> nodes;
    SlotLayout<LeafPlacement> leaves;
};

PartSlots partSlots(const std::vector<PendingPart>& pending,
                    const UninitialisedVector<LeafSpan>& spans) {
    PartSlots slots;
    for (const PendingPart& part : pending) {
        const std::size_t references = spans[part.binary].count;
        slots.nodes.append(references / 16 + 16);
        slots.leaves.append(references / 4 + 16);
    }
    return slots;
}

} // namespace

void spanBinaryNodes(const BvhNode* nodes, std::size_t first, std::size_t last, LeafSpan* spans) {
    for (std::size_t i = last; i-- > first;) { // children before their parent
        const BvhNode& n = nodes[i];
        if (n.isLeaf()) {
            spans[i] = {n.index, n.count, false};
        } else {
            const LeafSpan &left = spans[n.index], &right = spans[n.index + 1];
            const uint32_t count = left.count + right.count;
            spans[i] = {left.first, count,
                        count > kLeafMerge &&
                            (left.count > kLeafMerge || right.count > kLeafMerge)};
        }
    }
}

bool buildWideBvh(Bvh& bvh, const Scene& scene, const UninitialisedVector<uint32_t>& leafScene,
                  const UninitialisedVector<LeafSpan>& spans, bool pointBinaryLeaves,
                  BuildTeam& team, CollapseMemory& memory) {
    bvh.wideNodes.clear();
    bvh.triangleBlocks.clear();
    if (bvh.nodes.empty()) {
        return false;
    }
    BinaryTree tree(bvh, scene, leafScene, spans, pointBinaryLeaves);
    WidePart top;
    std::vector<PendingPart> pending;
    const uint32_t deferBelow =
        std::max(kMinPartTriangles, static_cast<uint32_t>(leafScene.size() / 128));
    Collapser(tree, top, deferBelow, &pending).run(0, 1);
    const PartSlots slots = partSlots(pending, spans);
    sizeSharedSlots(memory.nodes, slots.nodes);
    sizeSharedSlots(memory.leaves, slots.leaves);
    std::vector<WidePart> parts(pending.size());
    team.forEach(parts.size(), [&](std::size_t i) {
        WidePart part; // moved in once: the parts' vectors would share cache lines
        part.nodes = slotIn(memory.nodes, slots.nodes, i);
        part.leaves = slotIn(memory.leaves, slots.leaves, i);
        part.depth = pending[i].depth;
        Collapser(tree, part, 0, nullptr).run(pending[i].binary, pending[i].depth);
        parts[i] = std::move(part);
    });

    // Offsets: the top's nodes and blocks first, then each part's.
    std::vector<uint32_t> nodeAt(parts.size());
    std::size_t nodes = top.nodes.size();
    std::size_t blocks = top.lanesUsed.size();
    int depth = top.depth;
    bool overflow = top.overflow;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        nodeAt[i] = static_cast<uint32_t>(nodes);
        nodes += parts[i].nodes.size();
        parts[i].firstBlock = static_cast<uint32_t>(blocks); // checked below
        blocks += parts[i].lanesUsed.size();
        depth = std::max(depth, parts[i].depth);
        overflow = overflow || parts[i].overflow;
        top.nodes[pending[i].parent].child[pending[i].lane] = nodeAt[i];
    }
    if (overflow || blocks > kWideFirstBlockMask || (kWideLanes - 1) * depth + 1 > kWideStackSize) {
        return false;
    }
    // Every node and block is written below, once (resize leaves them unwritten, in huge pages:
    // uninitialised_allocator.h), first touched by the thread that fills it.
    bvh.wideNodes.resize(nodes);
    bvh.triangleBlocks.resize(blocks);
    std::copy(top.nodes.begin(), top.nodes.end(), bvh.wideNodes.begin());
    writeBlocks(top, tree, bvh.triangleBlocks.data());
    team.forEach(parts.size(), [&](std::size_t i) {
        relocate(parts[i], nodeAt[i]);
        std::copy(parts[i].nodes.begin(), parts[i].nodes.end(), bvh.wideNodes.begin() + nodeAt[i]);
        writeBlocks(parts[i], tree, bvh.triangleBlocks.data());
        parts[i] = WidePart{};
    });

    // Points the binary leaves at the blocks' lanes. A binary leaf lies inside one wide leaf,
    // whose triangles are consecutive lanes in leaf order, so its triangles stay consecutive.
    if (pointBinaryLeaves) {
        for (BvhNode& node : bvh.nodes) {
            if (node.isLeaf()) {
                node.index = tree.slotOf[node.index];
            }
        }
    }
    return true;
}

} // namespace raylab
