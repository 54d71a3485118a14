#pragma once
// Whether this system hands out transparent huge pages on request, as raylab's large arrays ask
// for them (core/huge_pages.h): tests of what those pages change skip where it does not.

#include <fstream>
#include <string>

namespace raylab::test {

// The kernel's setting, e.g. "always [madvise] never": the one in brackets is in force; empty
// where the system does not say.
inline std::string transparentHugePagesMode() {
    std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(file, modes);
    return modes;
}

// True where memory advised huge pages gets them ("madvise" or "always" in force).
inline bool hugePagesOnRequest() {
    const std::string modes = transparentHugePagesMode();
    return modes.find("[madvise]") != std::string::npos ||
           modes.find("[always]") != std::string::npos;
}

} // namespace raylab::test
