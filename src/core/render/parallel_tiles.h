#pragma once
// Splits an image into square tiles and hands them to threads dynamically: each thread takes the
// tiles of its own run of neighbouring tiles in row-major order, then helps the others from the
// back of theirs (parallel_tiles.cpp says why). Each pixel belongs to exactly one tile, so
// results never depend on the thread count.

#include <atomic>
#include <cstddef>
#include <functional>

namespace raylab {

struct TileRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0; // pixels [x0, x1) x [y0, y1)
};

// The number of worker threads `requested` means: 0 = every hardware thread; at least 1.
int resolveThreadCount(int requested);

struct TileLoopOptions {
    int tileSize = 32;
    int threads = 0;                           // as resolveThreadCount
    const std::atomic<bool>* cancel = nullptr; // checked before each tile
    // Called on the calling thread only, after each tile it finished, with the tiles done so far.
    std::function<void(std::size_t done, std::size_t total)> progress;
};

// Runs body(tile) once for each tile of a width x height image, from `threads` threads (the
// calling thread is one of them). Tile i, counted in row-major order, lies in thread w's run
// when w * n / threads <= i < (w + 1) * n / threads, for n tiles in all; one thread takes every
// tile in that order. Returns false when cancelled before all tiles were done.
bool forEachTile(int width, int height, const TileLoopOptions& options,
                 const std::function<void(const TileRect&)>& body);

} // namespace raylab
