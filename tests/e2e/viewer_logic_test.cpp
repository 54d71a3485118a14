// The viewer's logic without a window: the render thread's pictures equal core's render(), edits
// are validated, keys move what they say, screenshots never overwrite.

#include "core/cornell_box.h"
#include "core/render/display_transform.h"
#include "core/render/renderer.h"
#include "io/image_io.h"
#include "io/settings_json.h"
#include "navigation.h"
#include "render_worker.h"
#include "render_worker_support.h"
#include "screenshot.h"
#include "settings_edit.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <thread>

namespace raylab::viewer {
namespace {

RenderSettings smallSettings(int samples) {
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.samplesPerPixel = samples;
    s.threads = 2;
    return s;
}

using test::labBox;
using test::waitFinal;

std::vector<uint8_t> reference(const LoadedScene& loaded, const RenderSettings& settings) {
    const Framebuffer image = render(loaded.scene, loaded.bvh, settings);
    std::vector<uint8_t> bgra(4 * image.pixels.size());
    toRgba8(image.pixels, 1.0f, settings.display, settings.exposure, bgra, PixelOrder::Bgra);
    return bgra;
}

TEST(ViewerRenderWorker, FinalPictureEqualsCoreRender) {
    const auto box = labBox();
    RenderWorker worker;
    const RenderSettings settings = smallSettings(3);
    const ShownImage shown = waitFinal(worker, worker.submit({box, settings}));
    EXPECT_EQ(shown.settings.samplesPerPixel, 3);
    EXPECT_EQ(shown.bgra.width, 64);
    EXPECT_EQ(shown.bgra.height, 48);
    EXPECT_EQ(shown.bgra.pixels, reference(*box, settings));
}

TEST(ViewerRenderWorker, WakesTheUiForEveryPicture) {
    const auto box = labBox();
    std::atomic<int> wakes{0};
    RenderWorker worker(kPreviewBudgetSeconds, [&wakes] { ++wakes; });
    const ShownImage shown = waitFinal(worker, worker.submit({box, smallSettings(3)}));
    // One picture per pass, each published before its wake-up: the final (third) one has woken
    // the UI by the time the worker is idle.
    EXPECT_EQ(shown.serial, 3u);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (wakes.load() < 3 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_EQ(wakes.load(), 3);
}

TEST(ViewerRenderWorker, ChangeRestartsAndDisplayOnlyRemaps) {
    const auto box = labBox();
    RenderWorker worker;
    RenderSettings settings = smallSettings(2);
    worker.submit({box, settings});
    settings.camera.yawDegrees = 10.0f; // replaces the job at once, likely mid-pass
    const ShownImage moved = waitFinal(worker, worker.submit({box, settings}));
    EXPECT_EQ(moved.bgra.pixels, reference(*box, settings));
    EXPECT_EQ(moved.settings.camera.yawDegrees, 10.0f);

    settings.display = DisplayMode::Srgb;
    settings.exposure = 1.0f;
    const ShownImage remapped = waitFinal(worker, worker.submit({box, settings}));
    EXPECT_EQ(remapped.settings.samplesPerPixel, 2);
    EXPECT_EQ(remapped.bgra.pixels, reference(*box, settings));

    settings.samplesPerPixel = 4; // a higher cap continues accumulating
    const ShownImage more = waitFinal(worker, worker.submit({box, settings}));
    EXPECT_EQ(more.settings.samplesPerPixel, 4);
    EXPECT_EQ(more.bgra.pixels, reference(*box, settings));
}

TEST(ViewerRenderWorker, ReturningToThePictureReplacedLastResumesItsSamples) {
    const auto box = labBox();
    RenderWorker worker;
    RenderSettings lab = smallSettings(2);
    waitFinal(worker, worker.submit({box, lab}));
    RenderSettings observer = lab;
    observer.camera.position = {0.0f, 1.4f, -6.5f};
    lookAt(observer.camera, glm::vec3(0.0f));
    waitFinal(worker, worker.submit({box, observer}));
    const uint64_t passes = worker.totals().passes.count;
    EXPECT_EQ(passes, 4u);
    // Back to the lab camera: its 2 samples come back at once, no pass traced again.
    const ShownImage back = waitFinal(worker, worker.submit({box, lab}));
    EXPECT_EQ(back.settings.samplesPerPixel, 2);
    EXPECT_EQ(back.bgra.pixels, reference(*box, lab));
    EXPECT_EQ(worker.totals().passes.count, passes);
    // And the observer's picture was parked in turn; a higher cap continues it.
    observer.samplesPerPixel = 3;
    const ShownImage more = waitFinal(worker, worker.submit({box, observer}));
    EXPECT_EQ(more.bgra.pixels, reference(*box, observer));
    EXPECT_EQ(worker.totals().passes.count, passes + 1);
    // A lower cap than the parked samples starts again.
    lab.samplesPerPixel = 1;
    const ShownImage fewer = waitFinal(worker, worker.submit({box, lab}));
    EXPECT_EQ(fewer.bgra.pixels, reference(*box, lab));
    EXPECT_EQ(worker.totals().passes.count, passes + 2);
}

TEST(ViewerRenderWorker, LinearPictureEqualsCoreRender) {
    const auto box = labBox();
    RenderWorker worker;
    const RenderSettings settings = smallSettings(2);
    const ShownImage shown = waitFinal(worker, worker.submit({box, settings, true}));
    const Framebuffer expected = render(box->scene, box->bvh, settings);
    ASSERT_EQ(shown.linear.pixels.size(), expected.pixels.size());
    EXPECT_TRUE(shown.linear.pixels == expected.pixels);
}

TEST(ViewerRenderWorker, PreviewWhenPassesAreSlow) {
    const auto box = labBox();
    RenderWorker worker(1e-9); // any pass is "slow": every restart starts with a preview
    RenderSettings settings = smallSettings(1);
    waitFinal(worker, worker.submit({box, settings}));
    const uint64_t previewsBefore = worker.totals().previews.count;
    settings.camera.position.z = -2.5f;
    const uint64_t serial = worker.submit({box, settings});
    // takeLatest keeps only the newest picture, so the final one may replace the preview before
    // this thread looks: the worker's count says whether a preview ran; a preview caught in
    // passing must be enlarged to the render resolution.
    int previewsCaught = 0;
    ShownImage shown;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!(shown.jobSerial == serial && shown.final) &&
           std::chrono::steady_clock::now() < deadline) {
        if (worker.takeLatest(shown) && shown.jobSerial == serial && shown.preview) {
            ++previewsCaught;
            EXPECT_EQ(shown.bgra.width, 64);
            EXPECT_LT(shown.settings.width, 64);
            EXPECT_FALSE(shown.final);
        }
    }
    EXPECT_EQ(worker.totals().previews.count, previewsBefore + 1);
    EXPECT_LE(previewsCaught, 1);
    ASSERT_TRUE(shown.final);
    EXPECT_FALSE(shown.preview);
    EXPECT_EQ(shown.bgra.pixels, reference(*box, settings));
}

// A camera that moves faster than passes finish: first passes that fit the budget are not
// thrown away for the next step, each ends in a picture, and the last step's picture is exact.
TEST(ViewerRenderWorker, ShortFirstPassesFinishWhileTheCameraMoves) {
    const auto box = labBox();
    RenderWorker worker(10.0); // every measured pass fits
    RenderSettings settings = smallSettings(1);
    waitFinal(worker, worker.submit({box, settings})); // measures a pass
    uint64_t serial = 0;
    for (int step = 1; step <= 50; ++step) {
        settings.camera.yawDegrees = 0.5f * static_cast<float>(step);
        serial = worker.submit({box, settings});
        std::this_thread::sleep_for(std::chrono::microseconds(300));
    }
    const ShownImage last = waitFinal(worker, serial);
    EXPECT_EQ(last.bgra.pixels, reference(*box, settings));
    const PassTotals totals = worker.totals();
    EXPECT_EQ(totals.cancelled, 0u);
    EXPECT_EQ(totals.previews.count, 0u);
    EXPECT_GE(totals.passes.count, 2u);
}

// Passes that do not fit the budget are still cancelled by a new picture: each new job comes once
// its preview is shown, while its full pass (tens of milliseconds on one thread) runs.
TEST(ViewerRenderWorker, LongPassesAreCancelledByANewPicture) {
    const auto box = labBox();
    RenderWorker worker(1e-9); // no pass fits: previews first, full passes cancellable
    RenderSettings settings = smallSettings(1);
    settings.width = 1280;
    settings.height = 960;
    settings.threads = 1;
    uint64_t serial = worker.submit({box, settings});
    waitFinal(worker, serial);
    ShownImage shown;
    for (int step = 1; step <= 5; ++step) {
        settings.camera.yawDegrees = 0.5f * static_cast<float>(step);
        serial = worker.submit({box, settings});
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
        while (!(shown.jobSerial == serial && shown.preview) &&
               std::chrono::steady_clock::now() < deadline) {
            worker.takeLatest(shown);
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        ASSERT_EQ(shown.jobSerial, serial) << "no preview of job " << serial;
        std::this_thread::sleep_for(std::chrono::milliseconds(2)); // its full pass has begun
    }
    settings.camera.yawDegrees = 10.0f;
    serial = worker.submit({box, settings});
    const ShownImage last = waitFinal(worker, serial);
    EXPECT_EQ(last.bgra.pixels, reference(*box, settings));
    EXPECT_GE(worker.totals().cancelled, 3u) << worker.totals().passes.count << " passes, "
                                             << worker.totals().previews.count << " previews";
}

TEST(ViewerSettingsEdit, RefusesNonsenseAndKeepsTheCurrentSettings) {
    RenderSettings current;
    std::string why;
    RenderSettings edit = current;
    edit.light.intensity = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(acceptEdit(edit, current, why));
    EXPECT_FALSE(why.empty());
    EXPECT_EQ(current.light.intensity, 14.0f);
    edit = current;
    edit.light.intensity = -1.0f;
    EXPECT_FALSE(acceptEdit(edit, current, why));
    for (const float fov : {0.0f, 180.0f, -5.0f, std::numeric_limits<float>::infinity()}) {
        edit = current;
        edit.camera.verticalFovDegrees = fov;
        EXPECT_FALSE(acceptEdit(edit, current, why)) << fov;
    }
    EXPECT_EQ(current.camera.verticalFovDegrees, kLabVerticalFovDegrees);
    edit = current;
    edit.camera.verticalFovDegrees = 90.0f;
    EXPECT_TRUE(acceptEdit(edit, current, why));
    EXPECT_EQ(current.camera.verticalFovDegrees, 90.0f);
}

TEST(ViewerSettingsEdit, EpsilonSliderReachesZeroAndIsLogarithmic) {
    const float max = 0.1f;
    EXPECT_EQ(epsilonFromSlider(0.0f, max), 0.0f);
    EXPECT_FLOAT_EQ(epsilonFromSlider(1.0f, max), max);
    EXPECT_NEAR(epsilonFromSlider(0.5f, max), 1e-4f, 1e-9f); // three of six decades down
    EXPECT_EQ(sliderFromEpsilon(0.0f, max), 0.0f);
    EXPECT_NEAR(epsilonFromSlider(sliderFromEpsilon(1e-3f, max), max), 1e-3f, 1e-8f);
    EXPECT_GT(sliderFromEpsilon(1e-12f, max), 0.0f); // tiny but non-zero stays off zero
}

TEST(ViewerNavigation, KeysMoveWhatTheySay) {
    RenderSettings s;
    applyNavAction(NavAction::CameraForward, 0.1f, s);
    EXPECT_NEAR(s.camera.position.z, -2.9f, 1e-6f);
    applyNavAction(NavAction::CameraBack, 0.1f, s);
    EXPECT_NEAR(s.camera.position.z, -3.0f, 1e-6f);
    applyNavAction(NavAction::LightForward, 0.1f, s);
    EXPECT_NEAR(s.light.position.z, -0.6f, 1e-6f);
    applyNavAction(NavAction::LightDown, 0.1f, s);
    EXPECT_NEAR(s.light.position.y, 0.4f, 1e-6f);
    applyNavAction(NavAction::LightUp, 0.1f, s);
    applyNavAction(NavAction::LightRight, 0.1f, s); // the image's right is -x
    EXPECT_NEAR(s.light.position.x, -0.1f, 1e-6f);
    applyNavAction(NavAction::LightLeft, 0.1f, s);
    EXPECT_NEAR(s.light.position.x, 0.0f, 1e-6f);
    applyNavAction(NavAction::TurnLeft, 0.1f, s);
    EXPECT_EQ(s.camera.yawDegrees, kTurnStepDegrees);
    // After turning left, forward leans to +x (the image's left).
    applyNavAction(NavAction::CameraForward, 1.0f, s);
    EXPECT_GT(s.camera.position.x, 0.0f);
    turnCamera(0.0f, 500.0f, s);
    EXPECT_EQ(s.camera.pitchDegrees, kMaxPitchDegrees);
    turnCamera(400.0f, 0.0f, s);
    EXPECT_NEAR(s.camera.yawDegrees, kTurnStepDegrees + 40.0f, 1e-4f);
}

TEST(ViewerNavigation, FractionalStepsScaleMovesAndTurns) {
    RenderSettings s;
    applyNavAction(NavAction::CameraForward, 0.1f, s, 2.5f);
    EXPECT_NEAR(s.camera.position.z, -2.75f, 1e-6f);
    applyNavAction(NavAction::LightUp, 0.1f, s, 0.25f);
    EXPECT_NEAR(s.light.position.y, 0.525f, 1e-6f);
    applyNavAction(NavAction::TurnRight, 0.1f, s, 0.5f);
    EXPECT_NEAR(s.camera.yawDegrees, -0.5f * kTurnStepDegrees, 1e-6f);
    applyNavAction(NavAction::TurnLeft, 0.1f, s, 3.0f);
    EXPECT_NEAR(s.camera.yawDegrees, 2.5f * kTurnStepDegrees, 1e-5f);
    EXPECT_NEAR(s.camera.position.z, -2.75f, 1e-6f); // turning does not move
}

TEST(ViewerScreenshot, NumberedNamesNeverOverwrite) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() /
        ("raylab-viewer-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    { std::ofstream(dir / "raylab-0001.png") << "not mine"; }
    { std::ofstream(dir / "raylab-0002.json") << "{}"; }
    ShownImage shown;
    shown.bgra.width = 2;
    shown.bgra.height = 1;
    shown.bgra.pixels = {255, 0, 0, 255, 0, 0, 255, 255};
    shown.settings.width = 2;
    shown.settings.height = 1;
    std::string path, error;
    ASSERT_TRUE(saveNumberedScreenshot(dir.string(), shown, path, error)) << error;
    EXPECT_EQ(fs::path(path).filename(), "raylab-0003.png");
    EXPECT_TRUE(fs::exists(dir / "raylab-0003.json"));
    std::ifstream mine(dir / "raylab-0001.png");
    std::string text((std::istreambuf_iterator<char>(mine)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "not mine");
    Rgba8Image back;
    std::map<std::string, std::string> chunks;
    ASSERT_TRUE(readPng(path, back, error, &chunks)) << error;
    // Written in RGBA: the blue pixel first, then the red one.
    EXPECT_EQ(back.pixels, (std::vector<uint8_t>{0, 0, 255, 255, 255, 0, 0, 255}));
    EXPECT_EQ(back.pixels, rgbaOf(shown).pixels);
    RenderSettings fromChunk;
    ASSERT_TRUE(settingsFromJson(chunks.at(kSettingsChunk), fromChunk, error)) << error;
    EXPECT_EQ(fromChunk.width, 2);
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) {
        ++files;
    }
    EXPECT_EQ(files, 4u); // no temporary file left
    fs::remove_all(dir);
}

} // namespace
} // namespace raylab::viewer
