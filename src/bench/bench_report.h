#pragma once
// What raylab-bench measured, and how it prints it (text for people, JSON for scripts).

#include "bench_timing.h"
#include "core/ray.h"

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace raylab::bench {

// At most 1 closest hit in this many may disagree between raylab and Embree.
inline constexpr std::size_t kMaxDisagreement = 10000;

struct TracerFigures {
    double buildSeconds = 0.0;
    FrameTimes one; // 1 thread
    FrameTimes all; // BenchReport::threads threads
};

struct BenchReport {
    std::string scene;
    std::size_t triangles = 0, skipped = 0;
    int width = 0, height = 0, threads = 1, frames = 1;
    std::size_t primaryRays = 0, shadowRays = 0;
    std::size_t bvhBytes = 0;
    int bvhDepth = 0;
    std::size_t leafReferences = 0; // leaf triangles, pre-split copies included
    std::string traversal;          // "8-wide AVX2" or "scalar binary"
    TracerFigures raylab;           // packets of 8 rays, or single rays when !packets
    bool packets = false;
    TracerFigures raylabSingle;       // single rays, timed in the same turns (when packets)
    std::size_t packetMismatches = 0; // answers where packets and single rays differ (must be 0)
    // 8 x 8 pixel blocks through frustum candidates (bench_blocks.h), timed in the same turns.
    bool blocks = false;
    TracerFigures raylabBlocks;
    std::size_t blockMismatches = 0; // answers where blocks and packets differ (must be 0)
    std::size_t cameraBlocks = 0, cameraBlocksThroughCandidates = 0;
    std::size_t shadowBlocks = 0, shadowBlocksThroughCandidates = 0; // blocks with shadow rays
    bool hasEmbree = false;
    std::string embreeAbsent = "not built in"; // why there are no Embree figures
    TracerFigures embree;
    std::size_t disagreeingHits = 0;    // closest hits: different triangle and t not within 1e-4
    std::size_t disagreeingShadows = 0; // shadow rays: occluded for one and not the other
};

// Closest hits that disagree: not the same triangle, and not both found at distances within
// 1e-4 relative (nor both missed).
std::size_t countDisagreeingHits(const std::vector<Hit>& a, const std::vector<Hit>& b);

void printText(std::ostream& out, const BenchReport& report);
void printJson(std::ostream& out, const BenchReport& report);

} // namespace raylab::bench
