// libFuzzer target: screenshot_png (input_checks.h says what it checks).

#include "input_checks.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    if (const std::string problem = raylab::fuzz::checkScreenshotPng(data, size);
        !problem.empty()) {
        std::fprintf(stderr, "%s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
