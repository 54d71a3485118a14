// raylab-bench as a script runs it: its JSON keeps the keys scripts read, and the 8 x 8 pixel
// blocks (bench_blocks.h) give the packets' answers on every ray, partial blocks at the image's
// right and bottom edges included. Embree's three calls (embree_rays.h) report figures and agree
// with raylab, the bounce workload traces one bounce ray per hit, and bad bench flags end with
// one line on stderr and exit code 2. No test asserts a speed: only that figures exist and are
// positive, and how they relate by definition.

#include "bench/bench_system.h"
#include "test_assets.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace raylab {
namespace {

struct Outcome {
    int exitCode = -1;
    std::string out;
    std::string err; // only when runBench was asked to capture it
};

// Runs raylab-bench on scene (none: the box) with args, stdout captured; stderr captured into
// Outcome::err when captureErr, else passed on.
Outcome runBench(const std::string& scene, const std::string& args, bool captureErr = false) {
    Outcome result;
    std::ostringstream command;
    command << '\'' << RAYLAB_BENCH_EXE << "' ";
    if (!scene.empty()) {
        command << '\'' << scene << "' ";
    }
    command << args;
    const std::filesystem::path errPath =
        std::filesystem::path(testing::TempDir()) /
        ("bench_cli_err_" + std::to_string(reinterpret_cast<std::uintptr_t>(&result)) + ".txt");
    if (captureErr) {
        command << " 2>'" << errPath.string() << "'";
    }
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
    if (captureErr) {
        std::ifstream err(errPath);
        std::ostringstream text;
        text << err.rdbuf();
        result.err = text.str();
        std::filesystem::remove(errPath);
    }
    return result;
}

double mrays(const nlohmann::json& figures, const char* threads) {
    return figures.at(threads).at("mrays_per_s").get<double>();
}

bool hasEmbree(const nlohmann::json& j) { return !j.at("embree").is_null(); }

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
    ASSERT_TRUE(j.at("packets16").get<bool>());
    EXPECT_EQ(j.at("packet16_mismatches").get<int>(), 0);
    EXPECT_GT(mrays(j.at("raylab_packets16"), "one_thread"), 0.0);
    EXPECT_GT(mrays(j.at("raylab_packets16"), "all_threads"), 0.0);
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

// --no-shadows: camera rays only, every tracer and Embree still agreeing.
TEST(BenchCli, NoShadowsTracesNoShadowRays) {
    const Outcome with = runBench("", "--width 40 --height 24 --frames 1 --threads 1 --json");
    const Outcome without =
        runBench("", "--width 40 --height 24 --frames 1 --threads 1 --no-shadows --json");
    ASSERT_EQ(with.exitCode, 0) << with.out;
    ASSERT_EQ(without.exitCode, 0) << without.out;
    const nlohmann::json a = nlohmann::json::parse(with.out);
    const nlohmann::json b = nlohmann::json::parse(without.out);
    EXPECT_GT(a.at("shadow_rays").get<int>(), 0);
    EXPECT_EQ(b.at("shadow_rays").get<int>(), 0);
    EXPECT_EQ(b.at("primary_rays").get<int>(), 40 * 24);
    EXPECT_EQ(b.at("raylab").at("rays").get<int>(), 40 * 24);
    EXPECT_EQ(b.at("packet_mismatches").get<int>(), 0);
    EXPECT_EQ(b.at("packet16_mismatches").get<int>(), 0);
    if (hasEmbree(b)) {
        EXPECT_EQ(b.at("disagreeing_hits").get<int>(), 0);
        EXPECT_EQ(b.at("disagreeing_shadow_rays").get<int>(), 0);
    }
}

TEST(BenchCli, NoBlocksKeepsTheOtherKeys) {
    const Outcome r = runBench("", "--width 40 --height 24 --frames 1 --no-blocks --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_FALSE(j.at("blocks").get<bool>());
    EXPECT_FALSE(j.contains("raylab_blocks"));
    EXPECT_FALSE(j.at("packets16").get<bool>());
    EXPECT_TRUE(j.contains("raylab_single_ray"));
    EXPECT_EQ(j.at("packet_mismatches").get<int>(), 0);
}

TEST(BenchCli, RendererPassesOfBothIntegratorsThroughTheFilm) {
    const Outcome r = runBench("", "--width 40 --height 30 --frames 1 --no-embree --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j.contains("passes"));
    for (const char* integrator : {"lab", "path"}) {
        for (const char* threads : {"one_thread", "all_threads"}) {
            EXPECT_GT(j["passes"][integrator][threads]["msamples_per_s"].get<double>(), 0.0)
                << integrator << " " << threads;
        }
    }
    // A path sample traces several rays per pixel, the lab's at most two.
    EXPECT_LT(j["passes"]["path"]["one_thread"]["msamples_per_s"].get<double>(),
              j["passes"]["lab"]["one_thread"]["msamples_per_s"].get<double>());
    const Outcome none =
        runBench("", "--width 40 --height 30 --frames 1 --no-embree --no-passes --json");
    ASSERT_EQ(none.exitCode, 0) << none.out;
    EXPECT_FALSE(nlohmann::json::parse(none.out).contains("passes"));
}

TEST(BenchCli, TextNamesTheBlocks) {
    const Outcome r = runBench("", "--width 48 --height 20 --frames 1 --no-embree");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("raylab (blocks)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("answers differing from packets: 0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("blocks through frustum candidates: camera"), std::string::npos) << r.out;
    // A note names the kernel's DAMON threads where they run, and is absent where none does.
    const std::vector<std::string> monitors = bench::memoryAccessMonitors();
    const std::size_t note = r.out.find("note: the kernel's DAMON");
    EXPECT_EQ(note != std::string::npos, !monitors.empty()) << r.out;
    for (const std::string& name : monitors) {
        EXPECT_NE(r.out.find(name, note), std::string::npos) << r.out;
    }
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

constexpr const char* kEmbreeCallKeys[] = {"embree_single", "embree_packet16", "embree_stream"};

// A figures object as raylab-bench prints it: build time, rays per frame and, on 1 thread and on
// all threads, positive rays per second and frame times that agree with them.
void expectFigures(const nlohmann::json& f, std::size_t rays, const std::string& name) {
    SCOPED_TRACE(name);
    EXPECT_EQ(f.at("rays").get<std::size_t>(), rays);
    EXPECT_GE(f.at("build_ms").get<double>(), 0.0);
    for (const char* threads : {"one_thread", "all_threads"}) {
        const double m = mrays(f, threads);
        const double ms = f.at(threads).at("frame_ms").get<double>();
        EXPECT_GT(m, 0.0) << threads;
        EXPECT_GT(ms, 0.0) << threads;
        // Mrays/s = rays / frame time, both printed rounded to 3 decimals.
        const double rounding = 0.5 * (m + ms) + 0.001;
        EXPECT_NEAR(m * ms * 1e3, static_cast<double>(rays),
                    rounding + 1e-3 * static_cast<double>(rays))
            << threads;
    }
}

// The figures of raylab's own path ("raylab") without its first build, after checking that: the
// figures of one of raylab's tracers, which "raylab" repeats, and its first build in the
// process, which took at least as long as the best of its builds.
nlohmann::json pathFigures(const nlohmann::json& j) {
    nlohmann::json path = j.at("raylab");
    EXPECT_GE(path.at("first_build_ms").get<double>(), path.at("build_ms").get<double>());
    path.erase("first_build_ms");
    return path;
}

// The Embree part of a report: every call's figures over the same rays as raylab's, its ratio
// to raylab, its answers agreeing with raylab's, the best call the fastest, Embree's BVH.
void expectEmbreeReport(const nlohmann::json& j) {
    const auto rays = j.at("raylab").at("rays").get<std::size_t>();
    const auto primary = j.at("primary_rays").get<std::size_t>();
    const auto bounce = j.at("bounce_rays").get<std::size_t>();
    std::vector<std::string> calls;
    for (const char* key : {"one_thread", "all_threads"}) {
        double fastest = 0.0;
        for (const char* call : kEmbreeCallKeys) {
            const nlohmann::json& e = j.at(call);
            expectFigures(e, rays, call);
            fastest = std::max(fastest, mrays(e, key));
            // raylab's path over this call: the ratio of their frame times (each printed
            // rounded to 3 decimals).
            const double raylabMs = j.at("raylab").at(key).at("frame_ms").get<double>();
            const double embreeMs = e.at(key).at("frame_ms").get<double>();
            const double ratio = embreeMs / raylabMs;
            EXPECT_NEAR(e.at(std::string("ratio_") + key).get<double>(), ratio,
                        ratio * (0.0005 / raylabMs + 0.0005 / embreeMs + 1e-3) + 1e-4)
                << call;
            EXPECT_LE(e.at("disagreeing_hits").get<std::size_t>() * 10000, primary) << call;
            EXPECT_LE(e.at("disagreeing_bounce_hits").get<std::size_t>() * 10000, bounce) << call;
            EXPECT_LE(e.at("disagreeing_shadow_rays").get<std::size_t>(),
                      j.at("shadow_rays").get<std::size_t>())
                << call;
            calls.push_back(e.at("call").get<std::string>());
        }
        const nlohmann::json& best = j.at("embree_best");
        expectFigures(best, rays, "embree_best");
        EXPECT_DOUBLE_EQ(mrays(best, key), fastest) << key;
        EXPECT_NE(std::find(calls.begin(), calls.end(),
                            best.at(std::string("call_") + key).get<std::string>()),
                  calls.end());
    }
    const nlohmann::json& embree = j.at("embree");
    EXPECT_GT(embree.at("memory_bytes").get<std::size_t>(), 0u);
    EXPECT_GT(embree.at("geometry_bytes").get<std::size_t>(), 0u);
    EXPECT_GT(embree.at("build_ms").get<double>(), 0.0);
    EXPECT_GE(embree.at("first_build_ms").get<double>(), embree.at("build_ms").get<double>());
    EXPECT_EQ(mrays(embree, "one_thread"), mrays(j.at("embree_best"), "one_thread"));
}

TEST(BenchCli, PrimaryWorkloadReportsEveryEmbreeCall) {
    // 38 x 22: 4 x 4 and 8 x 8 pixel tiles cut at the right and bottom edges. (An odd width
    // puts a column of rays in the box's plane x = 0, through the seams of its walls' triangle
    // pairs, where Embree's single-ray test misses for some rows: 20 of 1,350 at 45 x 30.)
    const Outcome r = runBench("", "--width 38 --height 22 --frames 1 --threads 2 --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("workload").get<std::string>(), "primary");
    EXPECT_EQ(j.at("bounce_rays").get<int>(), 0);
    EXPECT_TRUE(j.at("bounce").is_null());
    const auto rays =
        j.at("primary_rays").get<std::size_t>() + j.at("shadow_rays").get<std::size_t>();
    EXPECT_EQ(j.at("primary_rays").get<int>(), 38 * 22);
    // The box's builds take microseconds: the build times are the best of the most builds.
    EXPECT_EQ(j.at("builds").get<int>(), 20);
    // The kernel's DAMON threads, as /proc lists them (an empty list where none runs).
    EXPECT_EQ(j.at("memory_access_monitors"), nlohmann::json(bench::memoryAccessMonitors()));
    // The keys scripts read, unchanged.
    expectFigures(j.at("raylab"), rays, "raylab");
    EXPECT_GT(j.at("bvh").at("memory_bytes").get<std::size_t>(), 0u);
    // The box has 30 triangles: the renderer traces it in blocks, and so does raylab's figure.
    EXPECT_EQ(j.at("raylab_path").get<std::string>(), "blocks");
    EXPECT_EQ(pathFigures(j), j.at("raylab_blocks"));
    expectFigures(j.at("raylab_packets"), rays, "raylab_packets");
    if (!hasEmbree(j)) {
        GTEST_SKIP() << "raylab-bench was built without Embree";
    }
    expectEmbreeReport(j);
    EXPECT_EQ(j.at("embree").at("isa").get<std::string>(), "default");
    EXPECT_EQ(j.at("disagreeing_hits").get<int>(), 0);
    EXPECT_EQ(j.at("disagreeing_shadow_rays").get<int>(), 0);
}

TEST(BenchCli, BounceWorkloadTracesOneBounceRayPerHit) {
    const Outcome r =
        runBench("", "--width 46 --height 30 --frames 1 --threads 2 --workload bounce --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("workload").get<std::string>(), "bounce");
    const auto primary = j.at("primary_rays").get<std::size_t>();
    const auto shadow = j.at("shadow_rays").get<std::size_t>();
    const auto bounce = j.at("bounce_rays").get<std::size_t>();
    // One bounce ray per primary hit: the lit hits (one shadow ray each) are some of them, and
    // from the lab's camera most pixels see the box.
    EXPECT_GE(bounce, shadow);
    EXPECT_LE(bounce, primary);
    EXPECT_GT(bounce, primary / 2);
    expectFigures(j.at("raylab"), primary + shadow + bounce, "raylab");
    expectFigures(j.at("raylab_single_ray"), primary + shadow + bounce, "raylab_single_ray");
    // The bounce rays alone.
    const nlohmann::json& b = j.at("bounce");
    EXPECT_EQ(b.at("rays").get<std::size_t>(), bounce);
    expectFigures(b.at("raylab"), bounce, "bounce raylab");
    if (!hasEmbree(j)) {
        GTEST_SKIP() << "raylab-bench was built without Embree";
    }
    expectEmbreeReport(j);
    for (const char* call : kEmbreeCallKeys) {
        expectFigures(b.at(call), bounce, std::string("bounce ") + call);
    }
    // The goal's ratio: raylab's closestHits over Embree's single-ray calls.
    EXPECT_EQ(b.at("ratio_one_thread"), b.at("embree_single").at("ratio_one_thread"));
}

TEST(BenchCli, BounceRaysAreTheSameInEveryRun) {
    const std::string args =
        "--width 40 --height 24 --frames 1 --workload bounce --no-embree --json";
    const Outcome one = runBench("", args + " --threads 1");
    const Outcome two = runBench("", args + " --threads 2");
    ASSERT_EQ(one.exitCode, 0) << one.out;
    ASSERT_EQ(two.exitCode, 0) << two.out;
    const nlohmann::json a = nlohmann::json::parse(one.out);
    const nlohmann::json b = nlohmann::json::parse(two.out);
    EXPECT_GT(a.at("bounce_rays").get<int>(), 0);
    EXPECT_EQ(a.at("bounce_rays"), b.at("bounce_rays"));
    EXPECT_EQ(a.at("shadow_rays"), b.at("shadow_rays"));
}

TEST(BenchCli, EmbreeIsaAvx2IsAccepted) {
    for (const char* flag : {"--embree-isa avx2", "--embree-isa=avx2"}) {
        SCOPED_TRACE(flag);
        const Outcome r =
            runBench("", std::string("--width 24 --height 16 --frames 1 --json ") + flag);
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const nlohmann::json j = nlohmann::json::parse(r.out);
        if (!hasEmbree(j)) {
            GTEST_SKIP() << "raylab-bench was built without Embree";
        }
        EXPECT_EQ(j.at("embree").at("isa").get<std::string>(), "avx2");
        expectEmbreeReport(j);
    }
}

TEST(BenchCli, BadBenchFlagsGiveOneLineAndExitCode2) {
    for (const char* args :
         {"--workload sideways", "--workload", "--workload=", "--embree-isa avx9", "--embree-isa",
          "--embree-isa=AVX2", "--spatial-budget -1", "--spatial-budget 1.5", "--presplit-budget=x",
          "--spatial-min-gain -0.5", "--spatial-min-gain=nan", "--scalar=1"}) {
        SCOPED_TRACE(args);
        const Outcome r = runBench("", std::string("--width 16 --height 16 --frames 1 ") + args,
                                   /*captureErr=*/true);
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_TRUE(r.out.empty()) << r.out;
        ASSERT_FALSE(r.err.empty());
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.err.back(), '\n');
        const std::string flag = std::string(args).substr(0, std::string(args).find_first_of(" ="));
        EXPECT_EQ(r.err.rfind("raylab-bench: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
    }
}

TEST(BenchCli, BunnyBounceRaysAgreeWithEmbree) {
    const auto bunny = test::asset("bunny/bun_zipper.ply");
    if (bunny.empty()) {
        GTEST_SKIP() << "shared assets not found";
    }
    const Outcome r = runBench(
        bunny.string(), "--width 96 --height 64 --frames 1 --threads 2 --workload bounce --json");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    // The bunny has 69,451 triangles: the renderer traces it in packets, two rows of a block
    // at a time (16 rays with AVX-512, else two packets of 8).
    EXPECT_EQ(j.at("raylab_path").get<std::string>(), "packets16");
    EXPECT_EQ(pathFigures(j), j.at("raylab_packets16"));
    EXPECT_EQ(j.at("packet16_mismatches").get<int>(), 0);
    EXPECT_GT(j.at("bounce_rays").get<int>(), 0);
    if (!hasEmbree(j)) {
        GTEST_SKIP() << "raylab-bench was built without Embree";
    }
    expectEmbreeReport(j);
    // A mesh's Embree BVH is of some size; per triangle, within reason.
    const auto triangles = j.at("triangles").get<std::size_t>();
    EXPECT_GT(j.at("embree").at("memory_bytes").get<std::size_t>(), 16 * triangles);
    EXPECT_LT(j.at("embree").at("memory_bytes").get<std::size_t>(), 1024 * triangles);
}

} // namespace
} // namespace raylab
