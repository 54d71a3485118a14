// Replays the mesh loader's fuzz corpus (tests/fuzz/corpus/mesh_loader) under the normal build:
// every file must load or fail cleanly, exactly as the libFuzzer target demands.

#include "mesh_loader_check.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size);

namespace {

TEST(FuzzCorpus, EveryFileLoadsOrFailsCleanly) {
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(RAYLAB_FUZZ_CORPUS_DIR)) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
        SCOPED_TRACE(entry.path().string());
        EXPECT_EQ(raylab::fuzz::checkMeshLoader(bytes.data(), bytes.size()), "");
        ++files;
    }
    EXPECT_GE(files, 10u);
}

TEST(FuzzCorpus, TargetEntryPointAcceptsEmptyInput) {
    EXPECT_EQ(LLVMFuzzerTestOneInput(nullptr, 0), 0);
    const uint8_t one = 0;
    EXPECT_EQ(LLVMFuzzerTestOneInput(&one, 1), 0);
}

} // namespace
