#pragma once
// What raylab-bench measured, and how it prints it (text for people, JSON for scripts).

#include "bench_passes.h"
#include "bench_rays.h"
#include "bench_timing.h"
#include "core/ray.h"

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace raylab::bench {

// At most 1 closest hit in this many may disagree between raylab and Embree.
inline constexpr std::size_t kMaxDisagreement = 10000;

struct TracerFigures {
    std::size_t rays = 0; // rays traced in one frame
    double buildSeconds = 0.0;
    FrameTimes one; // 1 thread
    FrameTimes all; // BenchReport::threads threads
};

// Rays per second, in millions, of a frame of f.rays rays that took `seconds`.
double mraysPerSecond(const TracerFigures& f, double seconds);

// Embree's three calls, in this order (embree_rays.h: EmbreeCall).
inline constexpr std::size_t kEmbreeCalls = 3;

struct EmbreeCallFigures {
    TracerFigures figures;
    std::size_t disagreeingHits = 0;       // camera rays' closest hits (countDisagreeingHits)
    std::size_t disagreeingShadows = 0;    // shadow rays: occluded for one and not the other
    std::size_t disagreeingBounceHits = 0; // bounce rays' closest hits
};

struct BenchReport {
    std::string scene;
    Workload workload = Workload::Primary;
    std::size_t triangles = 0, skipped = 0;
    int width = 0, height = 0, threads = 1, frames = 1;
    std::size_t primaryRays = 0, shadowRays = 0, bounceRays = 0;
    std::size_t bvhBytes = 0;
    int bvhDepth = 0;
    std::size_t leafReferences = 0; // leaf triangles, pre-split copies included
    std::string traversal;          // "8-wide AVX2" or "scalar binary"
    // The renderer's own path for this scene ("blocks", "packets16", "packets" or "single rays";
    // bounce rays one by one whatever the path), and its figures.
    std::string raylabPath;
    TracerFigures raylab;
    bool packets = false;
    TracerFigures raylabPackets;      // packets of 8 rays (when packets)
    TracerFigures raylabSingle;       // single rays, timed in the same turns (when packets)
    std::size_t packetMismatches = 0; // answers where packets and single rays differ (must be 0)
    // 8 x 8 pixel blocks through frustum candidates (bench_blocks.h), timed in the same turns.
    bool blocks = false;
    TracerFigures raylabBlocks;
    std::size_t blockMismatches = 0; // answers where blocks and packets differ (must be 0)
    std::size_t cameraBlocks = 0, cameraBlocksThroughCandidates = 0;
    std::size_t shadowBlocks = 0, shadowBlocksThroughCandidates = 0; // blocks with shadow rays
    // The same blocks as packets of 16 rays, full blocks as four 4 x 4 tiles and the others
    // two rows at a time (traceBlockInPacketPairs: AVX-512 where the CPU has it, else two 8-ray
    // packets), timed in the same turns.
    bool packets16 = false;
    TracerFigures raylabPackets16;
    std::size_t packet16Mismatches = 0; // answers where they and packets differ (must be 0)

    bool hasEmbree = false;
    std::string embreeAbsent = "not built in"; // why there are no Embree figures
    std::string embreeIsa;                     // empty: Embree's own choice
    double embreeBuildSeconds = 0.0;
    int builds = 0; // each build time is the best of this many builds (raylab's and Embree's)
    // Each side's first build in the process (raylab's, then Embree's): what a program that
    // builds once waits for, its memory new to the process.
    double raylabFirstBuildSeconds = 0.0, embreeFirstBuildSeconds = 0.0;
    std::size_t embreeBytes = 0, embreeGeometryBytes = 0; // EmbreeScene
    std::array<EmbreeCallFigures, kEmbreeCalls> embree;   // every ray of the workload
    // The bounce workload's bounce rays alone: raylab's single rays and each Embree call.
    TracerFigures bounceRaylab;
    std::array<TracerFigures, kEmbreeCalls> bounceEmbree;
    // The renderer's passes (bench_passes.h), M pixel samples per second, unless --no-passes.
    bool passes = false;
    PassFigures labPasses, pathPasses; // 1 sample a pass, as the viewer renders
    PassFigures labPassesOfMany;       // kSamplesPerPass samples a pass, as raylab-render does
    // The kernel's DAMON threads running during the run (bench_system.h): where there are any,
    // the report says that its figures may swing from frame to frame.
    std::vector<std::string> memoryAccessMonitors;
};

// The fastest Embree call on 1 thread (one = true) or on all threads.
std::size_t bestEmbreeCall(const BenchReport& report, bool one);

// Closest hits that disagree: not the same triangle, and not both found at distances within
// 1e-4 relative (nor both missed).
std::size_t countDisagreeingHits(const std::vector<Hit>& a, const std::vector<Hit>& b);

void printText(std::ostream& out, const BenchReport& report);
void printJson(std::ostream& out, const BenchReport& report);

} // namespace raylab::bench
