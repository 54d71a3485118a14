#include "render/parallel_tiles.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace raylab {

int resolveThreadCount(int requested) {
    if (requested > 0) {
        return requested;
    }
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

bool forEachTile(int width, int height, const TileLoopOptions& options,
                 const std::function<void(const TileRect&)>& body) {
    const int size = std::max(1, options.tileSize);
    const int tilesX = (width + size - 1) / size;
    const int tilesY = (height + size - 1) / size;
    const std::size_t total = static_cast<std::size_t>(std::max(0, tilesX)) * std::max(0, tilesY);
    if (total == 0) {
        return true;
    }
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> done{0};

    // Takes tiles until none is left or the loop is cancelled. Tiles go out in row-major order,
    // so the picture fills from the top.
    auto work = [&](bool reportProgress) {
        for (;;) {
            if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
                return;
            }
            const std::size_t index = next.fetch_add(1, std::memory_order_relaxed);
            if (index >= total) {
                return;
            }
            const int tx = static_cast<int>(index % tilesX);
            const int ty = static_cast<int>(index / tilesX);
            const TileRect tile{tx * size, ty * size, std::min(width, (tx + 1) * size),
                                std::min(height, (ty + 1) * size)};
            body(tile);
            const std::size_t finished = done.fetch_add(1, std::memory_order_acq_rel) + 1;
            if (reportProgress && options.progress) {
                options.progress(finished, total);
            }
        }
    };

    const int threads =
        static_cast<int>(std::min<std::size_t>(resolveThreadCount(options.threads), total));
    std::vector<std::jthread> helpers;
    helpers.reserve(static_cast<std::size_t>(threads - 1));
    for (int i = 1; i < threads; ++i) {
        helpers.emplace_back(work, false);
    }
    work(true);
    helpers.clear(); // joins
    return done.load(std::memory_order_acquire) == total;
}

} // namespace raylab
