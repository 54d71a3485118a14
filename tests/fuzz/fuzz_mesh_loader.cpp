// libFuzzer target for the mesh loader (see mesh_loader_check.h for what it checks).

#include "mesh_loader_check.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    if (const std::string problem = raylab::fuzz::checkMeshLoader(data, size); !problem.empty()) {
        std::fprintf(stderr, "mesh loader: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}

// Assimp leaks on some of its error paths; that is the system library's business, not a finding
// about our code, whose leaks are still reported.
extern "C" const char* __lsan_default_suppressions() { return "leak:libassimp.so\n"; }
