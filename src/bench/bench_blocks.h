#pragma once
// The bench's rays in 8 x 8 pixel blocks, traced as the renderer traces them
// (core/lab_shading_block.cpp): each row of a block is one packet of its pixels' camera rays, one
// frustum walk (core/bvh_frustum.h) collects the triangles any of them may meet, and each packet
// tests just those (closestHit8 when the frustum fails or holds too many). The block's shadow
// rays stay in the row and lane of their camera ray's pixel (lane masks) and share one frustum
// towards the light likewise (anyHit8 as the fallback). The rays are BenchRays' own, repacked
// before any timing.

#include "bench_rays.h"
#include "core/bvh/bvh.h"
#include "core/bvh/bvh_frustum.h"
#include "core/bvh/bvh_packet.h"
#include "core/camera.h"
#include "core/integrators/lab_shading.h"
#include "core/ray_packet.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace raylab::bench {

struct BlockedRays {
    // Block b's rows are packets [b * kPacketSize, b * kPacketSize + rows[b]) of both vectors;
    // a block at the image's right or bottom edge has fewer lanes or rows.
    std::vector<RayPacket> primary;
    std::vector<RayPacket> shadow; // lane i of row r: the shadow ray of that pixel, if any
    std::vector<uint8_t> rows;
    std::vector<std::size_t> blockOffset; // tile i's blocks: [offset[i], offset[i + 1])
    // Lane i of packet p is ray primaryRay[p * kPacketSize + i] of BenchRays::primary (kNoRay:
    // the lane is empty); likewise shadowRay for BenchRays::shadow.
    std::vector<uint32_t> primaryRay;
    std::vector<uint32_t> shadowRay;
    std::vector<uint8_t> blockShadowRays; // 1 when block b has at least one shadow ray
    std::vector<ImageRect> rect;          // block b's pixel centres (its rays pass through them)
    std::size_t blocks() const { return rows.size(); }
};

// How a block's pixels are laid out in its 8 packets: `Rows`, packet r is row r (lane i: column
// i); `Tiles4x4`, as the renderer traces a full block of a scene it does not trace in blocks
// (core/lab_shading_block.cpp): packets 2t and 2t + 1 are the upper and lower halves (4 x 2
// pixels) of the block's 4 x 4 tile t (tilePixel). Blocks at the image's right or bottom edge,
// with fewer rows or columns, keep their rows either way.
enum class BlockLayout { Rows, Tiles4x4 };

// Tile i's pixels in blocks of 8 x 8 from its top-left corner, row of blocks by row of blocks,
// as the lab integrator's fast pass (core/integrators/lab_pass.cpp) walks a tile.
BlockedRays blockRays(const BenchRays& rays, BlockLayout layout = BlockLayout::Rows);

// What tracing a block recorded: bit kCameraCandidates of flags[b] when its camera packets went
// through frustum candidates, kShadowCandidates likewise for its shadow packets.
inline constexpr uint8_t kCameraCandidates = 1;
inline constexpr uint8_t kShadowCandidates = 2;

struct BlockAnswers {
    std::vector<HitPacket> hits;    // per primary packet
    std::vector<unsigned> occluded; // per shadow packet: bit i, lane i is occluded
    std::vector<uint8_t> flags;     // per block
};

// Sized for `blocked`, so that tracing allocates nothing.
BlockAnswers makeBlockAnswers(const BlockedRays& blocked);

// traceBlock and traceBlockInPacketPairs trace a block's shadow rays only when it has any
// (blockShadowRays): the packets of a block without one are never read, and its occluded entries
// stay 0 (as makeBlockAnswers sets them), as Embree's packet sets hold no packet for a tile
// without shadow rays (embree_packets.cpp). The renderer's blocks make their shadow packets in
// registers and cache, where reading them back costs next to nothing; here they come from arrays
// larger than the caches.

// Traces block b as shadeLabBlock does: its camera rays (made by `camera`) through the frustum
// of its image rectangle; shadow rays go through a frustum only when `shadowFrustum` (the
// renderer's condition: shadow epsilon >= 0).
void traceBlock(const Bvh& bvh, const PrimaryRays& camera, const BlockedRays& blocked,
                std::size_t block, const glm::vec3& light, bool shadowFrustum,
                BlockAnswers& answers);

// Traces block b as shadeLabBlock does for a scene it does not trace in blocks: a full block whose
// image rectangle misses the scene (imageRectMissesScene; its rays made by `camera`) as misses,
// without reading its rays; else the camera rays of a block of 8 rows as one packet of 64
// (closestHit64, walked as carry.cameraWalks chooses), of fewer rows two by two as packets of 16
// (closestHit16), then every pair's shadow rays (anyHit16, with carry.lastOccluder), a last odd
// row as a packet of 8. The caller carries `carry` from block to block of a tile as the renderer
// does. With BlockLayout::Tiles4x4, a full block is four 4 x 4 tiles, as the renderer's. Sets no
// flags.
void traceBlockInPacketPairs(const Bvh& bvh, const PrimaryRays& camera, const BlockedRays& blocked,
                             std::size_t block, BlockAnswers& answers, TileCarry& carry);

} // namespace raylab::bench
