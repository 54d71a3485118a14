#pragma once
// raylab-bench's own flags, taken out of the command line before the shared parser
// (io/command_line.h) reads the rest.

#include "bench_rays.h"

#include <string>
#include <vector>

namespace raylab::bench {

struct BenchFlags {
    bool scalar = false;                   // --scalar: raylab's scalar reference traversal
    bool noEmbree = false;                 // --no-embree
    bool noPackets = false;                // --no-packets: raylab's single rays only
    bool noBlocks = false;                 // --no-blocks
    bool noPasses = false;                 // --no-passes: no renderer passes (bench_passes.h)
    float spatialBudget = -1.0f;           // --spatial-budget=F; < 0: BvhBuildOptions' default
    float presplitBudget = -1.0f;          // --presplit-budget=F; likewise
    Workload workload = Workload::Primary; // --workload primary|bounce
    std::string embreeIsa;                 // --embree-isa NAME; empty: Embree's own choice
    bool sizeGiven = false;                // --width or --height is among the other flags
};

// The instruction sets --embree-isa accepts, as Embree's "isa=" device configuration names them.
// Embree itself reads an unknown name as SSE2, so the bench refuses one instead.
bool isEmbreeIsa(const std::string& isa);

// Removes the bench's flags from args (args[0], the program, stays) and returns them. On a bad
// one, returns false with `error` set (one line, for exit code 2); args is then unspecified.
bool takeBenchFlags(std::vector<const char*>& args, BenchFlags& flags, std::string& error);

// The help text of the bench's own flags.
const char* benchFlagsHelp();

} // namespace raylab::bench
