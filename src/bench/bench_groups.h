#pragma once
// A workload's pixels in small square groups inside each tile: 4 x 4 for Embree's 16-ray packets,
// 8 x 8 for its ray streams, tile size for its single rays (then a group is the whole tile, in
// BenchRays' own order).

#include "bench_rays.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab::bench {

struct PixelGroups {
    int side = 0;
    // Group g's side x side slots, row-major: [g * side * side, (g + 1) * side * side). Each holds
    // the index of its pixel's primary ray (BenchRays::primary), or kNoRay where the group
    // reaches past its tile (at the image's right or bottom edge).
    std::vector<uint32_t> slots;
    std::vector<std::size_t> tileOffset; // tile i's groups: [offset[i], offset[i + 1])
    std::size_t slotsPerGroup() const { return static_cast<std::size_t>(side) * side; }
    std::size_t groups() const { return tileOffset.empty() ? 0 : tileOffset.back(); }
};

// Each tile's pixels in groups of side x side from the tile's top-left corner, row of groups by
// row of groups. 1 <= side <= rays.tileSize.
PixelGroups groupPixels(const BenchRays& rays, int side);

} // namespace raylab::bench
