#include "render/parallel_tiles.h"

#include <algorithm>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace raylab {

int resolveThreadCount(int requested) {
    if (requested > 0) {
        return requested;
    }
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

namespace {

// One worker's share of the tiles, [front, back) in row-major order: its owner takes them from
// the front; a worker whose own run is empty takes from the back of the run with the most left.
// Each run on a cache line of its own, as its owner writes it after every tile.
//
// Why runs: neighbouring tiles lie in neighbouring memory (a film's rows, the bench's rays and
// answers), and two threads on neighbouring tiles slow each other. Handed out one by one from a
// single counter, so that two threads took tiles in turn, the Zen 5 of PERFORMANCE.md traced the
// bunny's 16-ray packets at 12.4 us a tile on 1 thread but at 15-16 on each of 2, and at 12.5 on
// each of 2 that took one half of the picture each ("The tile loop").
struct alignas(64) TileRun {
    std::mutex mutex;
    std::size_t front = 0, back = 0;

    // The run's next tile from the front, or its last from the back; false when it is empty.
    bool take(bool fromBack, std::size_t& index) {
        const std::lock_guard lock(mutex);
        if (front == back) {
            return false;
        }
        index = fromBack ? --back : front++;
        return true;
    }

    std::size_t left() {
        const std::lock_guard lock(mutex);
        return back - front;
    }
};

} // namespace

bool forEachTile(int width, int height, const TileLoopOptions& options,
                 const std::function<void(const TileRect&)>& body) {
    const int size = std::max(1, options.tileSize);
    const int tilesX = (width + size - 1) / size;
    const int tilesY = (height + size - 1) / size;
    const std::size_t total = static_cast<std::size_t>(std::max(0, tilesX)) * std::max(0, tilesY);
    if (total == 0) {
        return true;
    }
    const int threads =
        static_cast<int>(std::min<std::size_t>(resolveThreadCount(options.threads), total));
    const auto runs = std::make_unique<TileRun[]>(static_cast<std::size_t>(threads));
    for (int w = 0; w < threads; ++w) {
        runs[w].front = total * static_cast<std::size_t>(w) / static_cast<std::size_t>(threads);
        runs[w].back = total * static_cast<std::size_t>(w + 1) / static_cast<std::size_t>(threads);
    }
    std::atomic<std::size_t> done{0};

    // The next tile for worker w: from its own run, else from the back of the fullest; false when
    // every run is empty.
    auto nextTile = [&](int w, std::size_t& index) {
        if (runs[w].take(false, index)) {
            return true;
        }
        for (;;) {
            TileRun* fullest = nullptr;
            std::size_t most = 0;
            for (int r = 0; r < threads; ++r) {
                if (const std::size_t left = runs[r].left(); left > most) {
                    most = left;
                    fullest = &runs[r];
                }
            }
            if (fullest == nullptr) {
                return false;
            }
            if (fullest->take(true, index)) {
                return true;
            }
        }
    };

    // Worker w takes tiles until none is left or the loop is cancelled.
    auto work = [&](int w) {
        std::size_t index = 0;
        while (!(options.cancel && options.cancel->load(std::memory_order_relaxed)) &&
               nextTile(w, index)) {
            const int tx = static_cast<int>(index % tilesX);
            const int ty = static_cast<int>(index / tilesX);
            const TileRect tile{tx * size, ty * size, std::min(width, (tx + 1) * size),
                                std::min(height, (ty + 1) * size)};
            body(tile);
            const std::size_t finished = done.fetch_add(1, std::memory_order_acq_rel) + 1;
            if (w == 0 && options.progress) {
                options.progress(finished, total);
            }
        }
    };

    std::vector<std::jthread> helpers;
    helpers.reserve(static_cast<std::size_t>(threads - 1));
    for (int w = 1; w < threads; ++w) {
        helpers.emplace_back(work, w);
    }
    work(0);
    helpers.clear(); // joins
    return done.load(std::memory_order_acquire) == total;
}

} // namespace raylab
