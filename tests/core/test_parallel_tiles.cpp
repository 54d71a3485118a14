// The tile loop: every pixel exactly once, for any size and thread count; which thread takes
// which tiles (runs of neighbours, the idle helping from the back); cancellation.

#include "core/render/parallel_tiles.h"

#include <atomic>
#include <chrono>
#include <gtest/gtest.h>
#include <mutex>
#include <thread>
#include <vector>

namespace raylab {
namespace {

TEST(ParallelTiles, CoversEveryPixelExactlyOnce) {
    for (const auto& [w, h] : {std::pair{1, 1}, {31, 33}, {64, 64}, {100, 7}, {1, 300}}) {
        for (int threads : {1, 2, 5}) {
            std::vector<std::atomic<int>> visits(static_cast<std::size_t>(w) * h);
            TileLoopOptions options;
            options.threads = threads;
            options.tileSize = 16;
            ASSERT_TRUE(forEachTile(w, h, options, [&](const TileRect& t) {
                ASSERT_LT(t.x0, t.x1);
                ASSERT_LT(t.y0, t.y1);
                for (int y = t.y0; y < t.y1; ++y) {
                    for (int x = t.x0; x < t.x1; ++x) {
                        visits[static_cast<std::size_t>(y) * w + x].fetch_add(1);
                    }
                }
            }));
            for (const auto& v : visits) {
                ASSERT_EQ(v.load(), 1) << w << "x" << h << ", " << threads << " threads";
            }
        }
    }
}

// Tile t's row-major index in a loop of tiles of `size` over an image `width` wide.
std::size_t indexOf(const TileRect& t, int width, int size) {
    const int tilesX = (width + size - 1) / size;
    return static_cast<std::size_t>(t.y0 / size) * tilesX + static_cast<std::size_t>(t.x0 / size);
}

// What each thread took, in the order it took it: taken[0] the calling thread's.
struct TakenTiles {
    std::mutex mutex;
    std::thread::id caller = std::this_thread::get_id();
    std::vector<std::size_t> taken[2];

    void add(std::size_t index) {
        const std::lock_guard lock(mutex);
        taken[std::this_thread::get_id() == caller ? 0 : 1].push_back(index);
    }
};

TEST(ParallelTiles, OneThreadTakesTheTilesInRowMajorOrder) {
    TileLoopOptions options;
    options.threads = 1;
    options.tileSize = 8;
    TakenTiles tiles;
    ASSERT_TRUE(
        forEachTile(100, 30, options, [&](const TileRect& t) { tiles.add(indexOf(t, 100, 8)); }));
    ASSERT_EQ(tiles.taken[0].size(), 13u * 4u);
    for (std::size_t i = 0; i < tiles.taken[0].size(); ++i) {
        EXPECT_EQ(tiles.taken[0][i], i);
    }
}

// Two threads that both keep working: each takes neighbouring tiles, not every other one, so
// that the owner changes at most three times along the row-major order (between the two runs,
// and where each run's owner met a helper taking from its back).
TEST(ParallelTiles, TwoThreadsTakeRunsOfNeighbouringTiles) {
    constexpr int kSize = 4, kWidth = 128, kHeight = 128; // 32 x 32 tiles
    TileLoopOptions options;
    options.threads = 2;
    options.tileSize = kSize;
    TakenTiles tiles;
    std::vector<int> owner(32 * 32, -1);
    ASSERT_TRUE(forEachTile(kWidth, kHeight, options, [&](const TileRect& t) {
        tiles.add(indexOf(t, kWidth, kSize));
        // About 20 us of work a tile, so that both threads are at work at once.
        const auto until = std::chrono::steady_clock::now() + std::chrono::microseconds(20);
        while (std::chrono::steady_clock::now() < until) {
        }
    }));
    for (int w = 0; w < 2; ++w) {
        for (const std::size_t i : tiles.taken[w]) {
            ASSERT_EQ(owner[i], -1) << "tile " << i << " taken twice";
            owner[i] = w;
        }
    }
    int changes = 0;
    for (std::size_t i = 0; i < owner.size(); ++i) {
        ASSERT_NE(owner[i], -1) << "tile " << i << " not taken";
        changes += i > 0 && owner[i] != owner[i - 1] ? 1 : 0;
    }
    EXPECT_LE(changes, 3);
}

// Whether `flag` was set within 30 s.
bool waitFor(const std::atomic<bool>& flag) {
    const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!flag.load() && std::chrono::steady_clock::now() < limit) {
        std::this_thread::yield();
    }
    return flag.load();
}

// The calling thread stays in its first tile until the helper, done with its own run (the
// second half, begun once the calling thread is in tile 0), has taken all the rest of the first
// half from its back, last tile first.
TEST(ParallelTiles, AThreadDoneWithItsRunTakesTheOthersFromTheBack) {
    constexpr int kSize = 16, kWidth = 64, kHeight = 64; // 4 x 4 tiles; runs [0, 8) and [8, 16)
    TileLoopOptions options;
    options.threads = 2;
    options.tileSize = kSize;
    TakenTiles tiles;
    std::atomic<bool> inTile0{false}, tile1Taken{false}, timedOut{false};
    ASSERT_TRUE(forEachTile(kWidth, kHeight, options, [&](const TileRect& t) {
        const std::size_t index = indexOf(t, kWidth, kSize);
        tiles.add(index);
        if (index == 0) {
            inTile0.store(true);
            timedOut.store(timedOut.load() || !waitFor(tile1Taken));
        } else if (index == 1) {
            tile1Taken.store(true);
        } else if (index == 8) {
            timedOut.store(timedOut.load() || !waitFor(inTile0));
        }
    }));
    ASSERT_FALSE(timedOut.load()) << "a thread waited 30 s for the other";
    EXPECT_EQ(tiles.taken[0], (std::vector<std::size_t>{0}));
    EXPECT_EQ(tiles.taken[1],
              (std::vector<std::size_t>{8, 9, 10, 11, 12, 13, 14, 15, 7, 6, 5, 4, 3, 2, 1}));
}

TEST(ParallelTiles, ZeroSizeDoesNothing) {
    int calls = 0;
    EXPECT_TRUE(forEachTile(0, 10, {}, [&](const TileRect&) { ++calls; }));
    EXPECT_TRUE(forEachTile(10, 0, {}, [&](const TileRect&) { ++calls; }));
    EXPECT_EQ(calls, 0);
}

TEST(ParallelTiles, CancellingMidwayStopsTakingTiles) {
    std::atomic<bool> cancel{false};
    std::atomic<int> calls{0};
    TileLoopOptions options;
    options.threads = 2;
    options.tileSize = 8;
    options.cancel = &cancel;
    const bool complete = forEachTile(256, 256, options, [&](const TileRect&) {
        if (calls.fetch_add(1) == 10) {
            cancel.store(true);
        }
    });
    EXPECT_FALSE(complete);
    EXPECT_LT(calls.load(), 32 * 32);
}

TEST(ParallelTiles, ResolvesZeroToTheHardware) {
    EXPECT_GE(resolveThreadCount(0), 1);
    EXPECT_EQ(resolveThreadCount(3), 3);
}

} // namespace
} // namespace raylab
