// Replays the seed corpora of the fuzz targets for partial files, settings JSON, command lines,
// PFM/EXR pictures and dropped screenshots (tests/fuzz/corpus/<name>) under the normal build: every
// input must be accepted whole or refused in one line, as the libFuzzer targets demand
// (input_checks.h).

#include "input_checks.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <vector>

namespace {

using Check = std::string (*)(const uint8_t*, std::size_t);

void replay(const char* name, Check check) {
    std::size_t files = 0;
    const std::filesystem::path dir = std::filesystem::path(RAYLAB_FUZZ_CORPORA_DIR) / name;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
        SCOPED_TRACE(entry.path().string());
        EXPECT_EQ(check(bytes.data(), bytes.size()), "");
        ++files;
    }
    EXPECT_GE(files, 2u) << dir;
    EXPECT_EQ(check(nullptr, 0), "");
}

TEST(FuzzInputsCorpus, PartialFiles) { replay("partial_file", raylab::fuzz::checkPartialFile); }
TEST(FuzzInputsCorpus, SettingsJson) { replay("settings_json", raylab::fuzz::checkSettingsJson); }
TEST(FuzzInputsCorpus, CommandLines) { replay("command_line", raylab::fuzz::checkCommandLine); }
TEST(FuzzInputsCorpus, LinearImages) { replay("linear_image", raylab::fuzz::checkLinearImage); }
TEST(FuzzInputsCorpus, ScreenshotPngs) {
    replay("screenshot_png", raylab::fuzz::checkScreenshotPng);
}

} // namespace
