#include "bench_system.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace raylab::bench {

std::vector<std::string> memoryAccessMonitors(const std::string& procRoot) {
    namespace fs = std::filesystem;
    std::vector<std::string> names;
    std::error_code error;
    fs::directory_iterator entries(procRoot, error);
    for (; !error && entries != fs::directory_iterator(); entries.increment(error)) {
        const std::string pid = entries->path().filename().string();
        if (pid.empty() ||
            !std::all_of(pid.begin(), pid.end(), [](char c) { return c >= '0' && c <= '9'; })) {
            continue;
        }
        // A process may end between the listing and the read: then there is no name to read.
        std::ifstream comm(entries->path() / "comm");
        std::string name;
        if (std::getline(comm, name) && name.rfind("kdamond", 0) == 0) {
            names.push_back(name);
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace raylab::bench
