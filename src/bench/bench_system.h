#pragma once
// What raylab-bench tells its reader about the system it measures on, beside the figures.

#include <string>
#include <vector>

namespace raylab::bench {

// The names of the kernel's DAMON threads ("kdamond.0", ...) running under `procRoot` (the proc
// file system: /proc), in name order; empty where there are none or no such directory. DAMON
// samples which memory is accessed by clearing and reading pages' accessed bits; on the
// paravirtualised Zen 5 guest of PERFORMANCE.md ("Machine and conditions") one monitoring the
// physical memory made the bench's frames swing by up to 3x, and stopping it made them hold.
std::vector<std::string> memoryAccessMonitors(const std::string& procRoot = "/proc");

} // namespace raylab::bench
