#pragma once
// The 8-wide form of the BVH that the SIMD traversal reads. It is collapsed from the binary BVH
// (bvh.h) after the build; the binary nodes stay as the scalar reference path.

#include <cstdint>

namespace raylab {

inline constexpr int kWideLanes = 8;

// Child references of BvhWideNode::child. An inner child is its index into Bvh::wideNodes (below
// 2^31). A leaf is kWideLeafFlag | (blocks - 1) << kWideBlockShift | first block, for 1 to 8
// blocks of Bvh::triangleBlocks starting at the first (below 2^27).
inline constexpr uint32_t kWideLeafFlag = 0x80000000u;
inline constexpr int kWideBlockShift = 27;
inline constexpr uint32_t kWideMaxLeafBlocks = 8;
inline constexpr uint32_t kWideFirstBlockMask = (1u << kWideBlockShift) - 1;
inline constexpr uint32_t kWideEmpty = 0xffffffffu; // unused slot (its box is empty too)

// An inner node with up to 8 children, structure of arrays so one AVX2 register holds one bound
// of all 8 children. Bounds are in world units; an unused slot has lower = +inf, upper = -inf, so
// no ray hits it. 224 bytes of data, padded to four cache lines.
struct alignas(64) BvhWideNode {
    float lower[3][kWideLanes]; // [axis][child]
    float upper[3][kWideLanes];
    uint32_t child[kWideLanes];
};
static_assert(sizeof(BvhWideNode) == 256);

// Eight triangles, structure of arrays: vertex[k][axis][lane] is vertex k of the lane's triangle.
// A leaf's triangles are consecutive lanes of its blocks, and leaves share blocks
// (bvh_collapse.cpp): testing a leaf tests its blocks' other triangles too, which never changes
// an answer (they are the scene's own). Lanes no leaf takes repeat the block's first triangle.
struct alignas(32) BvhTriangleBlock {
    float vertex[3][3][kWideLanes];
    uint32_t sceneIndex[kWideLanes];
};
static_assert(sizeof(BvhTriangleBlock) == 320);

} // namespace raylab
