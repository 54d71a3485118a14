#include "io/import_limits.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <unistd.h>

namespace raylab {

double defaultImportMemoryGiB() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) {
        return 2.0;
    }
    const double physicalGiB =
        static_cast<double>(pages) * static_cast<double>(pageSize) / (1024.0 * 1024.0 * 1024.0);
    return std::clamp(std::floor(physicalGiB / 4.0), 1.0, 4.0);
}

double effectiveImportMemoryGiB(const ImportLimits& limits) {
    return limits.memoryGiB > 0.0 ? limits.memoryGiB : defaultImportMemoryGiB();
}

bool parseImportLimit(const std::string& text, double max, double& out) {
    if (text.empty() || text.size() > 64) {
        return false;
    }
    const std::string copy = text; // strtod needs a terminated string
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(copy.c_str(), &end);
    if (errno != 0 || end != copy.c_str() + copy.size() || !std::isfinite(value) ||
        !(value > 0.0) || value > max) {
        return false;
    }
    out = value;
    return true;
}

} // namespace raylab
