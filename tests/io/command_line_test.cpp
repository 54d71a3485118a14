// The shared command line: every flag, both spellings of values, strict numbers, the settings
// file's place in the order, and the programs' own flags.

#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/scene_framing.h"
#include "io/command_line.h"
#include "io/settings_json.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <initializer_list>
#include <string>
#include <unistd.h>
#include <vector>

namespace raylab {
namespace {

namespace fs = std::filesystem;

struct Parsed {
    int code = -1;
    CommandLine line;
    std::string error;
};

Parsed parse(std::initializer_list<const char*> args, Program program = Program::Render) {
    std::vector<const char*> argv = {"prog"};
    argv.insert(argv.end(), args.begin(), args.end());
    Parsed p;
    p.code = parseCommandLine(static_cast<int>(argv.size()), argv.data(), program, p.line, p.error);
    return p;
}

TEST(CommandLine, DefaultsAreTheLabs) {
    const Parsed p = parse({"-o", "x.png"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_EQ(p.line.scene, "cornell");
    EXPECT_EQ(p.line.output, "x.png");
    EXPECT_EQ(p.line.settings.width, 500);
    EXPECT_EQ(p.line.settings.light.intensity, 14.0f);
    EXPECT_FALSE(p.line.cameraGiven);
    EXPECT_FALSE(p.line.lightGiven);
    EXPECT_FALSE(p.line.shadowEpsilonGiven);
    EXPECT_FALSE(p.line.lookAt.has_value());
}

TEST(CommandLine, EveryRenderFlag) {
    const Parsed p = parse({"scene.obj",
                            "--width",
                            "320",
                            "--height=240",
                            "--camera-pos",
                            "1,2.5,-3",
                            "--yaw",
                            "-30",
                            "--pitch=15",
                            "--look-at",
                            "0,0,0",
                            "--fov",
                            "40",
                            "--light-pos",
                            "0.5,1,-1",
                            "--light-power",
                            "20",
                            "--indirect",
                            "0.25",
                            "--shadow-eps",
                            "0.01",
                            "--no-shadows",
                            "--no-indirect",
                            "--spp",
                            "4",
                            "--threads",
                            "2",
                            "--display",
                            "srgb",
                            "--exposure",
                            "-1.5",
                            "--save-settings",
                            "s.json",
                            "-o",
                            "out.pfm"});
    ASSERT_EQ(p.code, 0) << p.error;
    const CommandLine& c = p.line;
    const RenderSettings& s = c.settings;
    EXPECT_EQ(c.scene, "scene.obj");
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 240);
    EXPECT_EQ(s.camera.position, glm::vec3(1.0f, 2.5f, -3.0f));
    EXPECT_EQ(s.camera.yawDegrees, -30.0f);
    EXPECT_EQ(s.camera.pitchDegrees, 15.0f);
    ASSERT_TRUE(c.lookAt.has_value());
    EXPECT_EQ(*c.lookAt, glm::vec3(0.0f));
    EXPECT_EQ(s.camera.verticalFovDegrees, 40.0f);
    EXPECT_EQ(s.light.position, glm::vec3(0.5f, 1.0f, -1.0f));
    EXPECT_EQ(s.light.color, glm::vec3(1.0f));
    EXPECT_EQ(s.light.intensity, 20.0f);
    EXPECT_EQ(s.indirectColor, glm::vec3(1.0f));
    EXPECT_EQ(s.indirectIntensity, 0.25f);
    EXPECT_EQ(s.shadowEpsilon, 0.01f);
    EXPECT_FALSE(s.shadows);
    EXPECT_FALSE(s.indirect);
    EXPECT_EQ(s.samplesPerPixel, 4);
    EXPECT_EQ(s.threads, 2);
    EXPECT_EQ(s.display, DisplayMode::Srgb);
    EXPECT_EQ(s.exposure, -1.5f);
    EXPECT_EQ(c.saveSettings, "s.json");
    EXPECT_EQ(c.output, "out.pfm");
    EXPECT_TRUE(c.cameraGiven);
    EXPECT_TRUE(c.lightGiven);
    EXPECT_TRUE(c.shadowEpsilonGiven);
}

TEST(CommandLine, ColouredPowerIsSplitIntoColourAndIntensity) {
    const Parsed p = parse({"--light-power", "10,5,0", "--indirect=0.2,0.4,0.1", "-o", "x.png"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_EQ(p.line.settings.light.color, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(p.line.settings.light.intensity, 10.0f);
    EXPECT_FLOAT_EQ(p.line.settings.indirectColor.x, 0.5f);
    EXPECT_EQ(p.line.settings.indirectColor.y, 1.0f);
    EXPECT_FLOAT_EQ(p.line.settings.indirectColor.z, 0.25f);
    EXPECT_EQ(p.line.settings.indirectIntensity, 0.4f);

    const Parsed zero = parse({"--light-power", "0,0,0", "-o", "x.png"});
    ASSERT_EQ(zero.code, 0) << zero.error;
    EXPECT_EQ(zero.line.settings.light.color, glm::vec3(1.0f));
    EXPECT_EQ(zero.line.settings.light.intensity, 0.0f);
}

TEST(CommandLine, FocalUsesTheFinalHeight) {
    // The lab's focal length equals the image height: 53.13 degrees, whatever the flag order.
    const Parsed p = parse({"--focal", "300", "--height", "300", "-o", "x.png"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_NEAR(p.line.settings.camera.verticalFovDegrees, kLabVerticalFovDegrees, 1e-3f);
    EXPECT_NEAR(p.line.settings.camera.verticalFovDegrees, verticalFovFromFocal(300.0f, 300), 0.0f);
    EXPECT_EQ(parse({"--focal", "10", "--fov", "30", "-o", "x.png"}).code, 2);
}

TEST(CommandLine, UnknownFlagMessage) {
    const Parsed p = parse({"--foo", "-o", "x.png"});
    EXPECT_EQ(p.code, 2);
    EXPECT_EQ(p.error, "unknown option '--foo' (see --help)");
    EXPECT_EQ(parse({"--foo=3", "-o", "x.png"}).error, "unknown option '--foo' (see --help)");
}

TEST(CommandLine, BadValuesAreUsageErrorsNamingTheFlag) {
    const std::vector<std::vector<const char*>> cases = {
        {"--width", "0"},
        {"--width", "16385"},
        {"--height", "-5"},
        {"--width", "12px"},
        {"--width", "1e3"},
        {"--width", " 5"},
        {"--width", "99999999999999"},
        {"--fov", "nan"},
        {"--fov", "inf"},
        {"--fov", "0"},
        {"--fov", "180"},
        {"--pitch", "90"},
        {"--yaw", "1e40"},
        {"--yaw", "+3"},
        {"--yaw", "0x10"},
        {"--yaw", ""},
        {"--camera-pos", "1,2"},
        {"--camera-pos", "1,2,3,4"},
        {"--camera-pos", "1,,3"},
        {"--camera-pos", "1,2,nan"},
        {"--look-at", "a,b,c"},
        {"--light-power", "-1"},
        {"--light-power", "1,-1,0"},
        {"--indirect", "-0.5"},
        {"--shadow-eps", "-1e-3"},
        {"--spp", "0"},
        {"--threads", "-1"},
        {"--display", "hdr"},
        {"--exposure", "100"},
        {"--focal", "0"},
        {"--focal", "-3"},
    };
    for (const auto& c : cases) {
        std::vector<const char*> argv = {"prog"};
        argv.insert(argv.end(), c.begin(), c.end());
        argv.push_back("-o");
        argv.push_back("x.png");
        CommandLine line;
        std::string error;
        EXPECT_EQ(parseCommandLine(static_cast<int>(argv.size()), argv.data(), Program::Render,
                                   line, error),
                  2)
            << c[0] << " " << c[1];
        EXPECT_EQ(error.rfind(c[0], 0), 0u) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

TEST(CommandLine, MissingValuesAndStrayValues) {
    EXPECT_EQ(parse({"-o", "x.png", "--width"}).code, 2);
    EXPECT_NE(parse({"-o", "x.png", "--width"}).error.find("needs a value"), std::string::npos);
    EXPECT_EQ(parse({"-o", "x.png", "--no-shadows=1"}).code, 2);
    EXPECT_EQ(parse({"-o"}).code, 2);
    EXPECT_EQ(parse({"a.obj", "b.obj", "-o", "x.png"}).code, 2);
}

TEST(CommandLine, OutputIsRequiredAndMustHaveAKnownExtension) {
    const Parsed none = parse({});
    EXPECT_EQ(none.code, 2);
    EXPECT_NE(none.error.find("-o"), std::string::npos);
    const Parsed jpg = parse({"-o", "x.jpg"});
    EXPECT_EQ(jpg.code, 2);
    EXPECT_NE(jpg.error.find(".jpg"), std::string::npos) << jpg.error;
    EXPECT_EQ(parse({"-o", "x.EXR"}).code, 0);
    EXPECT_EQ(parse({"--output=x.png"}).line.output, "x.png");
}

TEST(CommandLine, NegativeNumbersAreValuesAndDoubleDashEndsOptions) {
    const Parsed p = parse({"--yaw", "-45", "-o", "x.png", "--", "-odd-name.obj"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_EQ(p.line.settings.camera.yawDegrees, -45.0f);
    EXPECT_EQ(p.line.scene, "-odd-name.obj");
}

TEST(CommandLine, HelpWinsOverEverything) {
    const Parsed p = parse({"--foo", "--help"});
    EXPECT_EQ(p.code, 0);
    EXPECT_TRUE(p.line.help);
    EXPECT_TRUE(parse({"-h"}).line.help);
    const std::string text = usage(Program::Render);
    for (const char* flag :
         {"--width",    "--height",     "--camera-pos", "--yaw",         "--pitch",
          "--look-at",  "--fov",        "--focal",      "--light-pos",   "--light-power",
          "--indirect", "--shadow-eps", "--no-shadows", "--no-indirect", "--spp",
          "--threads",  "--display",    "--exposure",   "--settings",    "--save-settings",
          "--help",     "-o FILE"}) {
        EXPECT_NE(text.find(flag), std::string::npos) << flag;
    }
    EXPECT_EQ(text.find("--screenshot"), std::string::npos);
    EXPECT_NE(usage(Program::Viewer).find("--screenshot-dir"), std::string::npos);
    EXPECT_NE(usage(Program::Bench).find("--json"), std::string::npos);
}

TEST(CommandLine, ProgramsHaveTheirOwnFlags) {
    const Parsed viewer =
        parse({"--frames", "3", "--screenshot", "s.png", "--screenshot-dir", "shots", "bunny.ply"},
              Program::Viewer);
    ASSERT_EQ(viewer.code, 0) << viewer.error;
    EXPECT_EQ(viewer.line.frames, 3);
    EXPECT_EQ(viewer.line.screenshot, "s.png");
    EXPECT_EQ(viewer.line.screenshotDir, "shots");
    EXPECT_EQ(viewer.line.scene, "bunny.ply");
    EXPECT_EQ(parse({"-o", "x.png"}, Program::Viewer).code, 2);
    EXPECT_EQ(parse({"--screenshot", "s.gif"}, Program::Viewer).code, 2);

    const Parsed bench =
        parse({"--json", "--frames=2", "--width", "64", "--threads", "1"}, Program::Bench);
    ASSERT_EQ(bench.code, 0) << bench.error;
    EXPECT_TRUE(bench.line.json);
    EXPECT_EQ(bench.line.benchFrames, 2);
    EXPECT_EQ(bench.line.settings.width, 64);
    EXPECT_EQ(parse({"--frames", "0"}, Program::Bench).code, 2);
    EXPECT_EQ(parse({"--json", "-o", "x.png"}).code, 2);
    EXPECT_EQ(parse({"--frames", "1", "-o", "x.png"}).code, 2);
}

TEST(CommandLine, TheViewersOwnOptionsAndDefaults) {
    const Parsed defaults = parse({}, Program::Viewer);
    ASSERT_EQ(defaults.code, 0) << defaults.error;
    EXPECT_EQ(defaults.line.settings.samplesPerPixel, kViewerSampleCap);
    EXPECT_EQ(defaults.line.settings.width, kViewerWidth);
    EXPECT_EQ(defaults.line.settings.height, kViewerHeight);
    EXPECT_TRUE(defaults.line.viewer.showPanel);
    EXPECT_EQ(defaults.line.viewer.resolutionScale, 1.0f);
    EXPECT_EQ(defaults.line.viewer.uiScale, 0.0f); // the monitor's

    const Parsed given =
        parse({"--no-panel", "--resolution-scale", "0.5", "--ui-scale=2", "--readback", "r.png",
               "--frames", "3", "--stats", "s.json", "--drop", "d.obj", "--spp", "8", "--width",
               "200", "--record", "session.json"},
              Program::Viewer);
    ASSERT_EQ(given.code, 0) << given.error;
    EXPECT_FALSE(given.line.viewer.showPanel);
    EXPECT_EQ(given.line.viewer.resolutionScale, 0.5f);
    EXPECT_EQ(given.line.viewer.uiScale, 2.0f);
    EXPECT_EQ(given.line.viewer.readback, "r.png");
    EXPECT_EQ(given.line.viewer.stats, "s.json");
    EXPECT_EQ(given.line.viewer.drop, "d.obj");
    EXPECT_EQ(given.line.viewer.record, "session.json");
    const Parsed replay = parse({"--replay", "session.json"}, Program::Viewer);
    ASSERT_EQ(replay.code, 0) << replay.error;
    EXPECT_EQ(replay.line.viewer.replay, "session.json");
    EXPECT_EQ(given.line.settings.samplesPerPixel, 8);
    EXPECT_EQ(given.line.settings.width, 200);
    EXPECT_EQ(given.line.settings.height, RenderSettings{}.height); // one of them given: no default

    for (std::initializer_list<const char*> bad :
         {std::initializer_list<const char*>{"--ui-scale", "9"},
          {"--ui-scale", "nan"},
          {"--resolution-scale", "0"},
          {"--readback", "r.png"},
          {"--stats", ""},
          {"--drop"},
          {"--record", ""},
          {"--replay", "a.json", "--record", "b.json"},
          {"--replay", "a.json", "--frames", "3"}}) {
        const Parsed p = parse(bad, Program::Viewer);
        EXPECT_EQ(p.code, 2) << *bad.begin();
        EXPECT_NE(p.error.find(*bad.begin()), std::string::npos) << p.error;
    }
    // The viewer's options are the viewer's alone, and the bench's the bench's.
    EXPECT_EQ(parse({"--no-panel", "-o", "x.png"}).code, 2);
    EXPECT_EQ(parse({"--no-panel"}, Program::Bench).code, 2);
    EXPECT_EQ(parse({"--workload", "bounce"}, Program::Viewer).code, 2);
}

TEST(CommandLine, TheBenchsOwnOptionsAndDefaults) {
    const Parsed defaults = parse({}, Program::Bench);
    ASSERT_EQ(defaults.code, 0) << defaults.error;
    EXPECT_EQ(defaults.line.settings.width, kBenchWidth);
    EXPECT_EQ(defaults.line.settings.height, kBenchHeight);
    EXPECT_FALSE(defaults.line.bench.bounceWorkload);
    const Parsed given =
        parse({"--workload", "bounce", "--scalar", "--no-packets", "--no-blocks", "--no-passes",
               "--no-embree", "--spatial-budget=0", "--presplit-budget", "0.25", "--embree-isa",
               "avx2", "--height", "90", "--spatial-min-gain", "1.5"},
              Program::Bench);
    ASSERT_EQ(given.code, 0) << given.error;
    const BenchOptions& b = given.line.bench;
    EXPECT_TRUE(b.bounceWorkload && b.scalar && b.noPackets && b.noBlocks && b.noPasses &&
                b.noEmbree);
    EXPECT_EQ(b.spatialBudget, 0.0f);
    EXPECT_EQ(b.presplitBudget, 0.25f);
    EXPECT_EQ(b.spatialMinGain, 1.5f);
    EXPECT_EQ(b.embreeIsa, "avx2");
    EXPECT_EQ(given.line.settings.height, 90);
    EXPECT_EQ(given.line.settings.width, RenderSettings{}.width);
}

class SettingsFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        // A folder of its own: ctest runs this fixture's tests side by side.
        dir_ = fs::temp_directory_path() /
               ("raylab-command-line-test-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
                std::to_string(::getpid()));
        fs::create_directories(dir_);
        file_ = (dir_ / "s.json").string();
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
    std::string file_;
};

TEST_F(SettingsFileTest, FileFirstThenFlagsWhateverTheOrder) {
    std::ofstream(file_) << R"({"image": {"width": 100, "height": 80}, "light": {"intensity": 3},)"
                            R"( "camera": {"yaw": 12}, "scene": "saved.obj"})";
    const Parsed p = parse({"--width", "64", "--settings", file_.c_str(), "-o", "x.png"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_EQ(p.line.settings.width, 64);  // the flag wins, though it came first
    EXPECT_EQ(p.line.settings.height, 80); // from the file
    EXPECT_EQ(p.line.settings.light.intensity, 3.0f);
    EXPECT_TRUE(p.line.cameraGiven); // the file gave the yaw
    EXPECT_TRUE(p.line.given.cameraYaw);
    EXPECT_FALSE(p.line.given.cameraPosition);
    EXPECT_TRUE(p.line.given.lightIntensity);
    EXPECT_FALSE(p.line.lightGiven);
    EXPECT_EQ(p.line.scene, "saved.obj"); // no SCENE given: the file's
    EXPECT_EQ(parse({"other.ply", "--settings", file_.c_str(), "-o", "x.png"}).line.scene,
              "other.ply");
}

TEST_F(SettingsFileTest, AnObserverViewsFileKeepsTheLabCameraAndRendersTheObservers) {
    std::ofstream(file_) << R"({"camera": {"position": [0, 1.5, -6.5], "pitch": -13},)"
                            R"( "observer": {"lab_camera": {"position": [0, 0, -3], "yaw": 5}}})";
    const Parsed p = parse({"--settings", file_.c_str(), "-o", "x.png"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_EQ(p.line.settings.camera.position, glm::vec3(0.0f, 1.5f, -6.5f)); // the observer's
    ASSERT_TRUE(p.line.observedLabCamera.has_value());
    EXPECT_EQ(p.line.observedLabCamera->position, glm::vec3(0.0f, 0.0f, -3.0f));
    EXPECT_EQ(p.line.observedLabCamera->yawDegrees, 5.0f);
    std::ofstream(file_) << R"({"camera": {"yaw": 12}})";
    EXPECT_FALSE(parse({"--settings", file_.c_str(), "-o", "x.png"}).line.observedLabCamera);
}

TEST_F(SettingsFileTest, BadFilesAreErrorsWithCode1) {
    std::ofstream(file_) << R"({"light": {"intensity": -3}})";
    const Parsed bad = parse({"--settings", file_.c_str(), "-o", "x.png"});
    EXPECT_EQ(bad.code, 1);
    EXPECT_NE(bad.error.find("light.intensity"), std::string::npos) << bad.error;
    const Parsed missing = parse({"--settings=/nonexistent/s.json", "-o", "x.png"});
    EXPECT_EQ(missing.code, 1);
    EXPECT_NE(missing.error.find("/nonexistent/s.json"), std::string::npos) << missing.error;
}

TEST(FinishSettings, MeshIsFramedExceptWhatWasGiven) {
    Scene mesh;
    mesh.name = "m.obj";
    mesh.materials.push_back(Material{});
    mesh.triangles.push_back(
        Triangle{glm::vec3(10, 0, 0), glm::vec3(12, 0, 0), glm::vec3(10, 2, 0), 0});

    Parsed p = parse({"m.obj", "--light-power", "7", "--yaw", "5", "-o", "x.png"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_EQ(finishSettings(mesh, p.line), "");
    RenderSettings framed;
    frameScene(mesh, framed);
    const RenderSettings& s = p.line.settings;
    EXPECT_EQ(s.camera.position, framed.camera.position);
    EXPECT_EQ(s.camera.yawDegrees, 5.0f);               // given
    EXPECT_EQ(s.light.position, framed.light.position); // framed
    EXPECT_EQ(s.light.intensity, 7.0f);                 // given
    EXPECT_EQ(s.shadowEpsilon, framed.shadowEpsilon);

    // The built-in box is never framed.
    Parsed box = parse({"-o", "x.png"});
    EXPECT_EQ(finishSettings(makeCornellBox(), box.line), "");
    EXPECT_EQ(box.line.settings.camera.position, glm::vec3(0.0f, 0.0f, -3.0f));
}

TEST(FinishSettings, LookAtTurnsTheCamera) {
    Parsed p = parse({"--camera-pos", "0,0,0", "--look-at", "1,0,0", "-o", "x.png"});
    ASSERT_EQ(p.code, 0) << p.error;
    EXPECT_EQ(finishSettings(makeCornellBox(), p.line), "");
    const glm::vec3 f = forwardOf(p.line.settings.camera);
    EXPECT_NEAR(f.x, 1.0f, 1e-5f);
    EXPECT_NEAR(f.y, 0.0f, 1e-5f);
    EXPECT_NEAR(f.z, 0.0f, 1e-5f);
}

} // namespace
} // namespace raylab
