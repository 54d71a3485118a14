// A first build's page faults: every array of kHugePageArrayBytes (256 KiB) or more, the build's
// working arrays and the BVH's own, faults in 2 MiB at a time (core/huge_pages.h), so that a
// scene of tens of thousands of triangles, several of whose arrays are of 256 KiB to 1 MiB, takes
// tens of page faults rather than hundreds (each about 11 us in the Zen 5 guest of
// PERFORMANCE.md, "Memory and page faults").

#include "accel_scenes.h"
#include "core/bvh/bvh.h"
#include "huge_pages_mode.h"
#include "io/sanitizer_build.h"

#include <cstddef>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <sys/resource.h>

namespace raylab::accel_test {
namespace {

// This process's minor page faults so far, its threads' included.
long minorFaults() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_minflt;
}

// /proc/vmstat's count of huge page faults the kernel served with small pages (it had no free
// 2 MiB to give), over the whole system; -1 where it does not say.
long hugePageFallbacks() {
    std::ifstream vmstat("/proc/vmstat");
    std::string name;
    long value = 0;
    while (vmstat >> name >> value) {
        if (name == "thp_fault_fallback") {
            return value;
        }
    }
    return -1;
}

// 60,000 small triangles: 11.6 MB of arrays (the BVH's and those BvhBuildMemory keeps). With huge
// pages only from 1 MiB, its arrays under 1 MiB faulted in 4 KiB at a time: the first build (1
// thread) took 552-554 page faults and the next (2 threads, in memory the heap had kept of the
// first) 193-223; from 256 KiB, 165 and 45.
TEST(BvhFirstBuild, FaultsInItsArraysAHugePageAtATime) {
    if (!test::hugePagesOnRequest()) {
        GTEST_SKIP() << "transparent huge pages are off here";
    }
    if (kSanitizerBuild) {
        GTEST_SKIP() << "a sanitizer's allocator and shadow memory fault in pages of their own";
    }
    const Scene scene = makeTriangleSoup(60000, 0.01f, 23);
    struct Case {
        int threads;
        long mostFaults;
    };
    for (const Case c : {Case{1, 300}, Case{2, 120}}) {
        BvhBuildOptions options;
        options.threads = c.threads;
        BvhBuildMemory memory;
        Bvh bvh;
        const long fallbacksBefore = hugePageFallbacks();
        const long before = minorFaults();
        rebuildBvh(scene, options, memory, bvh);
        const long faults = minorFaults() - before;
        if (hugePageFallbacks() != fallbacksBefore) {
            GTEST_SKIP() << "the kernel had no free huge page for some of the arrays";
        }
        ASSERT_FALSE(bvh.wideNodes.empty());
        const std::size_t bytes = bvh.memoryBytes() + memory.bytes();
        EXPECT_GT(bytes, std::size_t{8} << 20) << c.threads << " threads";
        EXPECT_LE(faults, c.mostFaults) << c.threads << " threads, " << bytes << " bytes of arrays";
    }
}

} // namespace
} // namespace raylab::accel_test
