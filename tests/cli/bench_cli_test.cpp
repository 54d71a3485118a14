// raylab-bench as a script runs it: its JSON keeps the keys scripts read, and the 8 x 8 pixel
// blocks (bench_blocks.h) give the packets' answers on every ray, partial blocks at the image's
// right and bottom edges included.

#include "test_assets.h"

#include <array>
#include <cstdio>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace raylab {
namespace {

struct Outcome {
    int exitCode = -1;
    std::string out;
};

// Runs raylab-bench on scene (none: the box) with args, stdout captured, stderr passed on.
Outcome runBench(const std::string& scene, const std::string& args) {
    Outcome result;
    std::ostringstream command;
    command << '\'' << RAYLAB_BENCH_EXE << "' ";
    if (!scene.empty()) {
        command << '\'' << scene << "' ";
    }
    command << args;
    FILE* pipe = popen(command.str().c_str(), "r");
    if (pipe == nullptr) {
        return result;
    }
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
        result.out.append(buffer.data(), n);
    }
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    return result;
}

double mrays(const nlohmann::json& figures, const char* threads) {
    return figures.at(threads).at("mrays_per_s").get<double>();
}

// The keys every run with packets prints, and the blocks' figures and checks.
void expectBlockReport(const nlohmann::json& j) {
    for (const char* key : {"scene", "primary_rays", "shadow_rays", "raylab", "packets",
                            "raylab_single_ray", "packet_mismatches", "bvh", "embree"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
    EXPECT_EQ(j.at("packet_mismatches").get<int>(), 0);
    ASSERT_TRUE(j.at("blocks").get<bool>());
    EXPECT_EQ(j.at("block_mismatches").get<int>(), 0);
    EXPECT_GT(mrays(j.at("raylab_blocks"), "one_thread"), 0.0);
    EXPECT_GT(mrays(j.at("raylab_blocks"), "all_threads"), 0.0);
    EXPECT_LE(j.at("camera_blocks_through_candidates").get<int>(),
              j.at("camera_blocks").get<int>());
    EXPECT_LE(j.at("shadow_blocks_through_candidates").get<int>(),
              j.at("shadow_blocks").get<int>());
    EXPECT_LE(j.at("shadow_blocks").get<int>(), j.at("camera_blocks").get<int>());
    if (!j.at("embree").is_null()) {
        for (const char* key :
             {"ratio_one_thread", "ratio_all_threads", "disagreeing_hits",
              "disagreeing_shadow_rays", "blocks_ratio_one_thread", "blocks_ratio_all_threads"}) {
            EXPECT_TRUE(j.contains(key)) << key;
        }
    }
}

TEST(BenchCli, BoxBlocksMatchPacketsWithPartialBlocks) {
    // 61 x 29: tiles of 32 and 29 columns, 29 rows; blocks of 5 columns and of 5 rows at the edges.
    const Outcome r = runBench("", "--width 61 --height 29 --frames 1 --threads 2 --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    expectBlockReport(j);
    EXPECT_EQ(j.at("camera_blocks").get<int>(), 8 * 4);
    // The box: every block's frustum holds few triangles.
    EXPECT_EQ(j.at("camera_blocks_through_candidates").get<int>(), 8 * 4);
    EXPECT_GT(j.at("shadow_blocks").get<int>(), 0);
}

TEST(BenchCli, NoBlocksKeepsTheOtherKeys) {
    const Outcome r = runBench("", "--width 40 --height 24 --frames 1 --no-blocks --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_FALSE(j.at("blocks").get<bool>());
    EXPECT_FALSE(j.contains("raylab_blocks"));
    EXPECT_TRUE(j.contains("raylab_single_ray"));
    EXPECT_EQ(j.at("packet_mismatches").get<int>(), 0);
}

TEST(BenchCli, TextNamesTheBlocks) {
    const Outcome r = runBench("", "--width 48 --height 20 --frames 1 --no-embree");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("raylab (blocks)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("answers differing from packets: 0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("blocks through frustum candidates: camera"), std::string::npos) << r.out;
}

TEST(BenchCli, BunnyBlocksTakeBothPathsAndMatchPackets) {
    const auto bunny = test::asset("bunny/bun_zipper.ply");
    if (bunny.empty()) {
        GTEST_SKIP() << "shared assets not found";
    }
    // Near the bunny most frusta hold too many triangles (the packet fallback); around it none.
    const Outcome r = runBench(bunny.string(),
                               "--width 203 --height 77 --frames 1 --threads 2 --no-embree --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    expectBlockReport(j);
    const int camera = j.at("camera_blocks").get<int>();
    const int cameraCandidates = j.at("camera_blocks_through_candidates").get<int>();
    EXPECT_GT(cameraCandidates, 0);
    EXPECT_LT(cameraCandidates, camera);
    EXPECT_GT(j.at("shadow_blocks").get<int>(), 0);
}

} // namespace
} // namespace raylab
