#include "bench_timing.h"

#include "core/render/parallel_tiles.h"

#include <algorithm>
#include <chrono>

namespace raylab::bench {

FrameTimes timeFrames(const BenchRays& rays, int threads, int frames, const TileTracer& trace) {
    TileLoopOptions options;
    options.tileSize = rays.tileSize;
    options.threads = threads;
    FrameTimes times;
    times.bestSeconds = 1e30;
    double sum = 0.0;
    for (int frame = 0; frame < std::max(1, frames); ++frame) {
        const auto start = std::chrono::steady_clock::now();
        forEachTile(rays.width, rays.height, options, [&](const TileRect& tile) {
            trace(static_cast<std::size_t>(tileIndex(tile.x0, tile.y0, rays.width, rays.tileSize)));
        });
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        times.bestSeconds = std::min(times.bestSeconds, seconds);
        sum += seconds;
    }
    times.meanSeconds = sum / std::max(1, frames);
    return times;
}

} // namespace raylab::bench
