// libFuzzer target for the parent's reading of raylab-import's stream (see import_stream_check.h).

#include "import_stream_check.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    if (const std::string problem = raylab::fuzz::checkImportStream(data, size); !problem.empty()) {
        std::fprintf(stderr, "import stream: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
