#include "bench_groups.h"

#include <algorithm>

namespace raylab::bench {

PixelGroups groupPixels(const BenchRays& rays, int side) {
    PixelGroups groups;
    groups.side = side;
    groups.tileOffset.assign(1, 0);
    const int ts = rays.tileSize;
    const int tilesX = (rays.width + ts - 1) / ts;
    for (std::size_t tile = 0; tile < rays.tiles(); ++tile) {
        const int tx0 = static_cast<int>(tile % static_cast<std::size_t>(tilesX)) * ts;
        const int ty0 = static_cast<int>(tile / static_cast<std::size_t>(tilesX)) * ts;
        const int tx1 = std::min(rays.width, tx0 + ts);
        const int ty1 = std::min(rays.height, ty0 + ts);
        std::size_t count = 0;
        for (int y0 = ty0; y0 < ty1; y0 += side) {
            for (int x0 = tx0; x0 < tx1; x0 += side) {
                for (int y = y0; y < y0 + side; ++y) {
                    for (int x = x0; x < x0 + side; ++x) {
                        // Row-major inside the tile (bench_rays.h).
                        groups.slots.push_back(
                            x < tx1 && y < ty1
                                ? static_cast<uint32_t>(rays.primaryOffset[tile] +
                                                        static_cast<std::size_t>(y - ty0) *
                                                            (tx1 - tx0) +
                                                        static_cast<std::size_t>(x - tx0))
                                : kNoRay);
                    }
                }
                ++count;
            }
        }
        groups.tileOffset.push_back(groups.tileOffset.back() + count);
    }
    return groups;
}

} // namespace raylab::bench
