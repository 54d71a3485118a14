// Renders split over machines: raylab-render --samples / --crop / --partial and raylab-merge, run
// as a user runs them. A merge of parts that cover every pixel's samples 0..N-1 once is the file
// raylab-render --spp N writes, byte for byte (PFM and EXR) and pixel for pixel (PNG); anything
// else is refused in one line, exit 1, with no output.

#include "io/image_io.h"
#include "io/partial_file.h"
#include "io/settings_json.h"
#include "run_program.h"
#include "temp_dir_test.h"

#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace raylab {
namespace {

class MergeCli : public test::TempDirTest {
protected:
    Outcome render(std::vector<std::string> args) const {
        return runProgram(RAYLAB_RENDER_EXE, args, dir_);
    }
    Outcome merge(const std::vector<std::string>& args) const {
        return runProgram(RAYLAB_MERGE_EXE, args, dir_);
    }
    void renderOk(const std::vector<std::string>& args) const {
        const Outcome r = render(args);
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    // A merge that fails: exit 1, one line naming `mustContain`, and no output file.
    void expectRefused(const std::vector<std::string>& args, const std::string& mustContain) {
        const std::vector<std::string> before = files();
        const Outcome r = merge(args);
        SCOPED_TRACE(r.err);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_EQ(r.errLines(), 1);
        EXPECT_EQ(r.err.rfind("raylab-merge: ", 0), 0u);
        EXPECT_NE(r.err.find(mustContain), std::string::npos);
        EXPECT_EQ(files(), before);
    }
};

const std::vector<std::string> kSize = {"--width", "96", "--height", "72"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

TEST_F(MergeCli, SampleRangesMergeToTheSingleRenderBitForBitForBothIntegrators) {
    for (const char* integrator : {"lab", "path"}) {
        SCOPED_TRACE(integrator);
        const auto flags =
            with(kSize, {"--integrator", integrator, "--light-radius", "0.05", "--threads", "2"});
        renderOk(with(flags, {"--spp", "7", "-o", path("full.pfm")}));
        renderOk(with(flags, {"--spp", "7", "-o", path("full.exr")}));
        renderOk(with(flags, {"--spp", "7", "-o", path("full.png")}));
        // Several splits, parts rendered on one thread or two, given in any order.
        const std::vector<std::vector<std::string>> splits = {
            {"0:7"}, {"0:1", "1:7"}, {"0:3", "3:4", "4:7"}, {"0:2", "2:4", "4:6", "6:7"}};
        for (const std::vector<std::string>& ranges : splits) {
            std::vector<std::string> parts;
            for (std::size_t i = 0; i < ranges.size(); ++i) {
                const std::string part = path("part" + std::to_string(i) + ".exr");
                renderOk(with(flags, {"--samples", ranges[i], "--threads", i % 2 ? "1" : "2",
                                      "--partial", part}));
                parts.insert(parts.begin(), part); // reversed: the order must not matter
            }
            for (const char* extension : {".pfm", ".exr", ".png"}) {
                const std::string merged = path(std::string("merged") + extension);
                const Outcome r = merge(with(parts, {"-o", merged}));
                ASSERT_EQ(r.exitCode, 0) << r.err;
                if (std::string(extension) == ".png") {
                    Rgba8Image a;
                    Rgba8Image b;
                    std::string error;
                    ASSERT_TRUE(readPng(merged, a, error)) << error;
                    ASSERT_TRUE(readPng(path("full.png"), b, error)) << error;
                    EXPECT_EQ(a.pixels, b.pixels) << ranges.size() << " parts";
                } else {
                    EXPECT_EQ(slurp(merged), slurp(path(std::string("full") + extension)))
                        << ranges.size() << " parts, " << extension;
                }
            }
            for (const std::string& part : parts) {
                std::filesystem::remove(part);
            }
        }
    }
}

TEST_F(MergeCli, CropsAndRangesTogetherMergeToTheWholeRender) {
    const auto flags = with(kSize, {"--integrator", "path", "--spp", "4"});
    renderOk(with(flags, {"-o", path("full.pfm")}));
    // Top band all samples; bottom-left two ranges; bottom-right one crop.
    renderOk(with(flags, {"--crop", "0,0,96,30", "--partial", path("top.exr")}));
    renderOk(with(kSize, {"--integrator", "path", "--samples", "0:1", "--crop", "0,30,50,72",
                          "--partial", path("bl0.exr")}));
    renderOk(with(kSize, {"--integrator", "path", "--samples", "1:4", "--crop", "0,30,50,72",
                          "--partial", path("bl1.exr")}));
    renderOk(with(flags, {"--crop", "50,30,96,72", "--partial", path("br.exr")}));
    const Outcome r = merge({path("bl1.exr"), path("top.exr"), path("br.exr"), path("bl0.exr"),
                             "-o", path("merged.pfm")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(slurp(path("merged.pfm")), slurp(path("full.pfm")));

    // A crop written as a picture is those pixels of the whole one.
    renderOk(with(flags, {"--crop", "50,30,96,72", "-o", path("crop.pfm")}));
    Framebuffer crop;
    Framebuffer full;
    std::string error;
    ASSERT_TRUE(readPfm(path("crop.pfm"), crop, error)) << error;
    ASSERT_TRUE(readPfm(path("full.pfm"), full, error)) << error;
    ASSERT_EQ(crop.width, 46);
    ASSERT_EQ(crop.height, 42);
    for (int y = 0; y < crop.height; ++y) {
        for (int x = 0; x < crop.width; ++x) {
            ASSERT_EQ(crop.at(x, y), full.at(50 + x, 30 + y)) << x << ", " << y;
        }
    }
}

TEST_F(MergeCli, PartsThatDoNotFitAreRefusedByName) {
    const auto flags = with(kSize, {"--integrator", "path"});
    renderOk(with(flags, {"--samples", "0:2", "--partial", path("a.exr")}));
    renderOk(with(flags, {"--samples", "2:4", "--partial", path("b.exr")}));
    renderOk(with(flags, {"--samples", "4:6", "--partial", path("c.exr")}));
    renderOk(with(flags, {"--samples", "1:3", "--partial", path("overlap.exr")}));
    renderOk(
        with(flags, {"--samples", "2:4", "--crop", "0,0,96,40", "--partial", path("top.exr")}));
    renderOk(with(
        flags, {"--samples", "2:4", "--light-pos", "0,0.4,-0.7", "--partial", path("moved.exr")}));
    renderOk(with(flags, {"--samples", "2:4", "--width", "80", "--partial", path("narrow.exr")}));
    // Another scene, written here so that the test needs no shared asset.
    std::ofstream(path("triangle.obj")) << "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n";
    renderOk(
        with(flags, {"--samples", "2:4", "--partial", path("other.exr"), path("triangle.obj")}));
    renderOk(with(flags, {"-o", path("plain.exr")}));
    const std::string out = path("out.png");
    expectRefused({path("a.exr"), path("c.exr"), "-o", out},
                  "samples 2:4 of pixels 0,0 to 96,72 are missing");
    expectRefused({path("b.exr"), path("c.exr"), "-o", out}, "samples 0:2 of pixels");
    expectRefused({path("a.exr"), path("overlap.exr"), path("b.exr"), "-o", out},
                  "are in two parts");
    expectRefused({path("a.exr"), path("top.exr"), "-o", out},
                  "samples 2:4 of pixels 0,40 to 96,72 are missing");
    expectRefused({path("a.exr"), path("moved.exr"), "-o", out}, "other settings");
    expectRefused({path("a.exr"), path("narrow.exr"), "-o", out}, "80x72 picture");
    expectRefused({path("a.exr"), path("other.exr"), "-o", out}, "another scene");
    expectRefused({path("a.exr"), path("plain.exr"), "-o", out}, "not a raylab partial");
    expectRefused({path("a.exr"), path("missing.exr"), "-o", out}, "missing.exr");
    // Re-rendering only the missing range completes the picture.
    const Outcome r = merge({path("a.exr"), path("c.exr"), path("b.exr"), "-o", out});
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST_F(MergeCli, BadFlagsAreUsageErrors) {
    const std::string p = path("p.exr");
    for (const auto& [args, message] :
         std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--samples", "4:2", "--partial", p}, "--samples"},
             {{"--samples", "x", "--partial", p}, "--samples"},
             {{"--crop", "0,0,10", "--partial", p}, "--crop"},
             {{"--crop", "5,0,2,4", "--partial", p}, "--crop"},
             {{"--width", "40", "--crop", "0,0,41,4", "--partial", p}, "not inside"},
             {{"--partial", path("p.pfm")}, "--partial"}}) {
        const Outcome r = render(args);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(r.errLines(), 1) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    }
    EXPECT_EQ(files(), std::vector<std::string>{});
    const Outcome noOutput = merge({path("a.exr")});
    EXPECT_EQ(noOutput.exitCode, 2);
    EXPECT_EQ(merge({"-o", path("x.png")}).exitCode, 2);
    EXPECT_EQ(merge({path("a.exr"), "-o", path("x.txt")}).exitCode, 2);
    EXPECT_EQ(files(), std::vector<std::string>{});
}

} // namespace
} // namespace raylab

namespace raylab {
namespace {

TEST_F(MergeCli, TurntableFramesRenderOneCameraEachAndTravelThroughAFile) {
    const Outcome saved = render({"--turntable", "6", "--save-frames", path("turntable.json")});
    ASSERT_EQ(saved.exitCode, 0) << saved.err;
    RenderSettings ignored;
    SettingsJsonExtras extras;
    std::string error;
    ASSERT_TRUE(loadSettingsFile(path("turntable.json"), ignored, extras, error)) << error;
    ASSERT_EQ(extras.frames.size(), 6u);
    // Frame K from the file is frame K of the turntable made on the spot, and differs from frame
    // K + 1.
    renderOk(with(
        kSize, {"--frames-from", path("turntable.json"), "--frame", "2", "-o", path("file.pfm")}));
    renderOk(with(kSize, {"--turntable", "6", "--frame", "2", "-o", path("direct.pfm")}));
    renderOk(with(kSize, {"--turntable", "6", "--frame", "3", "-o", path("next.pfm")}));
    EXPECT_EQ(slurp(path("file.pfm")), slurp(path("direct.pfm")));
    EXPECT_NE(slurp(path("file.pfm")), slurp(path("next.pfm")));
    // The settings file of the render holds frame 2's camera.
    renderOk(with(kSize, {"--turntable", "6", "--frame", "2", "-o", path("f.png"),
                          "--save-settings", path("f.json")}));
    RenderSettings frameSettings;
    ASSERT_TRUE(loadSettingsFile(path("f.json"), frameSettings, error)) << error;
    EXPECT_EQ(frameSettings.camera, extras.frames[2]);

    for (const auto& [args, message] :
         std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--frame", "1", "-o", path("x.png")}, "no frames"},
             {{"--turntable", "3", "--frame", "3", "-o", path("x.png")}, "there are 3 frames"},
             {{"--frames-from", path("none.json"), "--frame", "0", "-o", path("x.png")},
              "none.json"},
             {{"--turntable", "0", "-o", path("x.png")}, "--turntable"},
             {{"--save-frames", path("y.json")}, "no frames to save"}}) {
        const Outcome r = render(args);
        EXPECT_NE(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.errLines(), 1) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    }
}

} // namespace
} // namespace raylab
