// The tile loop: every pixel exactly once, for any size and thread count; cancellation.

#include "core/render/parallel_tiles.h"

#include <atomic>
#include <gtest/gtest.h>
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
