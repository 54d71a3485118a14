#pragma once
// Times tracing a BenchRays workload: every tile traced once per frame, tiles handed to threads
// dynamically (core forEachTile, the renderer's scheduler), best frame of several.

#include "bench_rays.h"

#include <cstddef>
#include <functional>

namespace raylab::bench {

// Traces tile `tile` of the workload: its primary rays, then its shadow rays.
using TileTracer = std::function<void(std::size_t tile)>;

struct FrameTimes {
    double bestSeconds = 0.0; // the fastest frame
    double meanSeconds = 0.0;
};

FrameTimes timeFrames(const BenchRays& rays, int threads, int frames, const TileTracer& trace);

} // namespace raylab::bench
