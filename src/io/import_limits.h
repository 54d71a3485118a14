#pragma once
// The limits raylab-import runs under: its address space and its wall-clock time. The parent
// enforces the time (it kills the helper); the helper sets the memory limit on itself before it
// opens the file.

#include <string>

namespace raylab {

struct ImportLimits {
    double memoryGiB = 0.0; // 0: defaultImportMemoryGiB()
    double seconds = 60.0;  // wall clock, from spawn to the last byte
};

// A share of physical memory that leaves the viewer room: a quarter of it, between 1 and 4 GiB.
double defaultImportMemoryGiB();

// The limit in force: memoryGiB, or the default when it is 0.
double effectiveImportMemoryGiB(const ImportLimits& limits);

// Parses a limit given on the command line ("4", "0.5"): finite and > 0 and at most `max`.
// Returns false for 0, negative, NaN, infinite, too large or malformed values.
bool parseImportLimit(const std::string& text, double max, double& out);

inline constexpr double kMaxImportMemoryGiB = 1024.0;
inline constexpr double kMaxImportSeconds = 86400.0;

} // namespace raylab
