#pragma once
// A workload's rays in Embree's own layouts, converted before any timing, and traced with one of
// Embree's calls (DESIGN.md section 6):
//  - Single: rtcIntersect1 / rtcOccluded1, one ray at a time, in BenchRays' order, with an
//    incoherent context (Embree's call for incoherent rays);
//  - Packet16: rtcIntersect16 / rtcOccluded16 on 4 x 4 pixel tiles (a pixel's ray in lane
//    4 * row + column, lanes without a ray masked off), with a coherent context;
//  - Stream: rtcIntersect1M / rtcOccluded1M on 8 x 8 pixel tiles (a tile's rays in pixel order,
//    packed), with a coherent context.
// Bounce rays are incoherent: every call traces them with an incoherent context.

#include "bench_rays.h"
#include "embree_scene.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace raylab::bench {

// In the order of BenchReport::embree.
enum class EmbreeCall { Single, Packet16, Stream };

// The ray sets of a workload, as bits: which ones a traceTile traces.
inline constexpr unsigned kPrimarySet = 1;
inline constexpr unsigned kShadowSet = 2;
inline constexpr unsigned kBounceSet = 4;
inline constexpr unsigned kAllSets = kPrimarySet | kShadowSet | kBounceSet;

// Embree's answers, in BenchRays' order.
struct EmbreeAnswers {
    std::vector<Hit> primary;      // Hit::triangle the scene's index, t, u and v Embree's
    std::vector<uint8_t> occluded; // per shadow ray: 1 when occluded
    std::vector<Hit> bounce;
};

class EmbreeRays {
public:
    virtual ~EmbreeRays() = default;
    // Untimed, before each frame: every ray of `sets` as it was made (Embree shortens tfar to the
    // hit and sets it to -inf for an occluded ray), its hit cleared.
    virtual void reset(unsigned sets) = 0;
    // Traces tile `tile`'s rays of `sets` (kPrimarySet | ...), with flush-to-zero and
    // denormals-are-zero set on the calling thread for the time of the call. Threads may trace
    // different tiles at once. Allocates nothing.
    virtual void traceTile(std::size_t tile, unsigned sets) = 0;
    // Untimed: the answers of the rays as the last frame left them.
    virtual EmbreeAnswers answers() const = 0;
};

// The rays of `rays` (all of its sets) in the layout of `call`, ready to trace on `scene`, which
// must outlive the result; `rays` must too (reset() reads it).
std::unique_ptr<EmbreeRays> makeEmbreeRays(EmbreeCall call, const EmbreeScene& scene,
                                           const BenchRays& rays);

} // namespace raylab::bench
