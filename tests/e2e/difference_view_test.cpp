// The compare's difference mode without a window: the diverging colour scale, composing the signed
// difference of two linear pictures, the render thread's difference pictures (from the two sides'
// means, switched to and rescaled without a new pass), and the screenshot's records of it.

#include "core/render/renderer.h"
#include "difference_view.h"
#include "io/settings_json.h"
#include "render_worker.h"
#include "render_worker_support.h"
#include "screenshot.h"
#include "split_view.h"

#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

namespace raylab::viewer {
namespace {

using Rgb = std::array<uint8_t, 3>;

TEST(DifferenceView, ZeroIsBlackPositiveRedNegativeBlueAndTheScaleIsFullColour) {
    EXPECT_EQ(differenceColour(0.0f, 0.1f), (Rgb{0, 0, 0}));
    EXPECT_EQ(differenceColour(0.1f, 0.1f), (Rgb{255, 0, 0}));
    EXPECT_EQ(differenceColour(-0.1f, 0.1f), (Rgb{0, 0, 255}));
    EXPECT_EQ(differenceColour(0.05f, 0.1f), (Rgb{128, 0, 0}));  // round(127.5)
    EXPECT_EQ(differenceColour(-0.025f, 0.1f), (Rgb{0, 0, 64})); // round(63.75)
    EXPECT_EQ(differenceColour(7.0f, 0.1f), (Rgb{255, 0, 0}));   // clamped
    EXPECT_EQ(differenceColour(-7.0f, 0.1f), (Rgb{0, 0, 255}));
    EXPECT_EQ(differenceColour(0.05f, 1.0f), (Rgb{13, 0, 0})); // a larger scale: dimmer
    EXPECT_EQ(differenceColour(std::nanf(""), 1.0f), (Rgb{0, 0, 0}));
    EXPECT_STREQ(toString(CompareMode::Difference), "difference");
    EXPECT_STREQ(toString(CompareMode::Wipe), "wipe");
}

TEST(DifferenceView, ComposeKeepsTheSignedChannelsAndColoursTheirMean) {
    Framebuffer live(2, 1), a(2, 1);
    live.at(0, 0) = {0.5f, 0.5f, 0.5f};
    a.at(0, 0) = {0.5f, 0.5f, 0.5f}; // the same: black
    live.at(1, 0) = {0.1f, 0.2f, 0.3f};
    a.at(1, 0) = {0.4f, 0.2f, 0.3f}; // mean difference -0.1: full blue at 0.1
    Framebuffer difference;
    std::vector<uint8_t> bgra(8), rgba(8);
    composeDifference(live, a, 0.1f, difference, bgra, PixelOrder::Bgra);
    composeDifference(live, a, 0.1f, difference, rgba, PixelOrder::Rgba);
    EXPECT_EQ(difference.width, 2);
    EXPECT_EQ(difference.at(0, 0), glm::vec3(0.0f));
    EXPECT_EQ(difference.at(1, 0), live.at(1, 0) - a.at(1, 0));
    EXPECT_EQ(bgra, (std::vector<uint8_t>{0, 0, 0, 255, 255, 0, 0, 255}));
    EXPECT_EQ(rgba, (std::vector<uint8_t>{0, 0, 0, 255, 0, 0, 255, 255}));
}

TEST(DifferenceView, TheWorkerShowsTheDifferenceOfTheSidesMeansAndRescalesWithoutAPass) {
    const auto box = test::labBox();
    RenderWorker worker;
    RenderSettings live;
    live.width = 40;
    live.height = 30;
    live.samplesPerPixel = 2;
    live.threads = 2;
    RenderSettings a = live;
    a.light.position.x += 0.3f; // A: the light elsewhere
    RenderJob job{box, live, true};
    job.compare = a;
    job.compareMode = CompareMode::Difference;
    job.differenceScale = 0.2f;
    const ShownImage shown = test::waitFinal(worker, worker.submit(job));
    EXPECT_EQ(shown.compareMode, CompareMode::Difference);
    EXPECT_EQ(shown.differenceScale, 0.2f);
    const Framebuffer liveMean = render(box->scene, box->bvh, live);
    const Framebuffer aMean = render(box->scene, box->bvh, a);
    Framebuffer expected;
    std::vector<uint8_t> bytes(4 * 40 * 30);
    composeDifference(liveMean, aMean, 0.2f, expected, bytes, PixelOrder::Bgra);
    EXPECT_EQ(shown.linear.pixels, expected.pixels);
    EXPECT_EQ(shown.bgra.pixels, bytes);
    int red = 0, blue = 0;
    for (std::size_t i = 0; i < bytes.size(); i += 4) {
        red += bytes[i + 2] > 0;
        blue += bytes[i] > 0;
    }
    EXPECT_GT(red, 0);
    EXPECT_GT(blue, 0);

    // Another scale, then back to the wipe: re-mapped, no pass.
    const PassTotals before = worker.totals();
    job.differenceScale = 0.05f;
    const ShownImage rescaled = test::waitFinal(worker, worker.submit(job));
    composeDifference(liveMean, aMean, 0.05f, expected, bytes, PixelOrder::Bgra);
    EXPECT_EQ(rescaled.bgra.pixels, bytes);
    job.compareMode = CompareMode::Wipe;
    const ShownImage wiped = test::waitFinal(worker, worker.submit(job));
    EXPECT_EQ(wiped.compareMode, CompareMode::Wipe);
    EXPECT_NE(wiped.bgra.pixels, bytes);
    EXPECT_EQ(worker.totals().passes.count, before.passes.count);
}

TEST(DifferenceView, AScreenshotOfTheDifferenceIsItsPictureAndBothFilesRecordTheScale) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("raylab-difference-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    ShownImage shown;
    shown.settings.width = 2;
    shown.settings.height = 1;
    shown.compare = shown.settings;
    shown.compare->light.position.x = 0.25f;
    shown.compareMode = CompareMode::Difference;
    shown.differenceScale = 0.125f;
    shown.bgra.width = 2;
    shown.bgra.height = 1;
    shown.bgra.pixels = {0, 0, 0, 255, 255, 0, 0, 255}; // black, blue (B, G, R, A)
    shown.linear = Framebuffer(2, 1);
    shown.linear.at(1, 0) = {-0.5f, -0.25f, 0.0f};
    std::string error;
    const std::string png = (dir / "d.png").string();
    ASSERT_TRUE(saveScreenshot(png, shown, error)) << error;
    Rgba8Image read;
    ASSERT_TRUE(readPng(png, read, error)) << error;
    EXPECT_EQ(read.pixels, (std::vector<uint8_t>{0, 0, 0, 255, 0, 0, 255, 255}));
    for (const char* file : {"d.json", "d-right.json"}) {
        RenderSettings settings;
        SettingsJsonExtras extras;
        ASSERT_TRUE(loadSettingsFile((dir / file).string(), settings, extras, error)) << error;
        ASSERT_TRUE(extras.split.has_value()) << file;
        EXPECT_EQ(extras.split->difference, 0.125f) << file;
    }
    // The linear picture written is the signed difference.
    const std::string pfm = (dir / "d.pfm").string();
    ASSERT_TRUE(saveScreenshot(pfm, shown, error)) << error;
    Framebuffer back;
    ASSERT_TRUE(readPfm(pfm, back, error)) << error;
    EXPECT_EQ(back.at(1, 0), glm::vec3(-0.5f, -0.25f, 0.0f));
    std::filesystem::remove_all(dir);

    // A wipe writes no "difference"; a bad one is refused.
    SettingsFileExtras wipe;
    wipe.split = SplitRecord{0.5f, "left", "x.json"};
    EXPECT_EQ(settingsToJson(RenderSettings(), "cornell", wipe).find("difference"),
              std::string::npos);
    RenderSettings settings;
    SettingsJsonExtras extras;
    EXPECT_FALSE(settingsFromJson(R"({"split": {"difference": -1}})", settings, extras, error));
    EXPECT_NE(error.find("split.difference"), std::string::npos) << error;
}

} // namespace
} // namespace raylab::viewer
