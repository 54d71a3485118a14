// The A/B split without a window: composing two pictures at the divider, grabbing it, the other
// integrator, and the render thread converging both sides of a split job on their own films.

#include "core/cornell_box.h"
#include "core/render/display_transform.h"
#include "core/render/renderer.h"
#include "io/settings_json.h"
#include "render_worker.h"
#include "render_worker_support.h"
#include "split_view.h"

#include <chrono>
#include <gtest/gtest.h>
#include <thread>

namespace raylab::viewer {
namespace {

TEST(SplitView, TheDividerColumnIsRoundedAndClamped) {
    EXPECT_EQ(splitColumn(100, 0.5f), 50);
    EXPECT_EQ(splitColumn(100, 0.333f), 33);
    EXPECT_EQ(splitColumn(100, 0.0f), 0);
    EXPECT_EQ(splitColumn(100, 1.0f), 100);
    EXPECT_EQ(splitColumn(100, -3.0f), 0);
    EXPECT_EQ(splitColumn(100, 7.0f), 100);
    EXPECT_TRUE(grabsDivider(52.0, 100, 0.5f));
    EXPECT_TRUE(grabsDivider(42.0, 100, 0.5f));
    EXPECT_FALSE(grabsDivider(41.0, 100, 0.5f));
    EXPECT_FALSE(grabsDivider(90.0, 100, 0.5f));
}

TEST(SplitView, ComposeTakesTheLeftColumnsFromLeftAndTheRestFromRight) {
    const int width = 5;
    const int height = 3;
    std::vector<uint8_t> left(4 * width * height, 10);
    std::vector<uint8_t> right(4 * width * height, 200);
    std::vector<uint8_t> out(left.size(), 0);
    composeSplit(left, right, width, height, 0.4f, out); // columns 0, 1 from the left
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const uint8_t expected = x < 2 ? 10 : 200;
            for (int c = 0; c < 4; ++c) {
                ASSERT_EQ(out[static_cast<std::size_t>(4 * (y * width + x) + c)], expected)
                    << x << ", " << y;
            }
        }
    }
    composeSplit(left, right, width, height, 0.4f, left); // in place
    EXPECT_EQ(left, out);

    Framebuffer a(width, height);
    Framebuffer b(width, height);
    std::fill(a.pixels.begin(), a.pixels.end(), glm::vec3(1.0f));
    std::fill(b.pixels.begin(), b.pixels.end(), glm::vec3(2.0f));
    composeSplit(a, b, 0.6f); // columns 0, 1, 2 stay
    EXPECT_EQ(a.at(2, 1), glm::vec3(1.0f));
    EXPECT_EQ(a.at(3, 1), glm::vec3(2.0f));
}

TEST(SplitView, TheRightSideIsTheOtherIntegrator) {
    RenderSettings lab;
    EXPECT_EQ(otherIntegrator(lab).integrator, Integrator::Path);
    RenderSettings path;
    path.integrator = Integrator::Path;
    const RenderSettings other = otherIntegrator(path);
    EXPECT_EQ(other.integrator, Integrator::Lab);
    RenderSettings same = other;
    same.integrator = Integrator::Path;
    EXPECT_EQ(same, path); // nothing else changed
}

TEST(SplitView, ASnapshotComparesAtTheLivePicturesSize) {
    RenderSettings live;
    live.width = 300;
    live.height = 200;
    live.threads = 2;
    live.samplesPerPixel = 9;
    RenderSettings snapshot;
    snapshot.shadowEpsilon = 0.0f;
    snapshot.width = 10;
    const RenderSettings right = splitCompare(live, &snapshot);
    EXPECT_EQ(right.shadowEpsilon, 0.0f);
    EXPECT_EQ(right.width, 300);
    EXPECT_EQ(right.height, 200);
    EXPECT_EQ(right.threads, 2);
    EXPECT_EQ(right.samplesPerPixel, 9);
    EXPECT_EQ(settingsDifferences(live, right),
              std::vector<std::string>{"shadow epsilon 0.001 -> 0"});
    EXPECT_EQ(splitCompare(live, nullptr), otherIntegrator(live));
}

TEST(SplitView, SettingsFilesRecordTheirSide) {
    RenderSettings s;
    SettingsFileExtras file;
    file.split = SplitRecord{0.25f, "right", "a.json"};
    const std::string text = settingsToJson(s, "cornell", file);
    RenderSettings read;
    SettingsJsonExtras extras;
    std::string error;
    ASSERT_TRUE(settingsFromJson(text, read, extras, error)) << error;
    ASSERT_TRUE(extras.split.has_value());
    EXPECT_EQ(*extras.split, (SplitRecord{0.25f, "right", "a.json"}));
    EXPECT_EQ(read, s);
    EXPECT_FALSE(settingsFromJson(R"({"split": {"divider": 2}})", read, extras, error));
    EXPECT_NE(error.find("split.divider"), std::string::npos) << error;
    EXPECT_FALSE(settingsFromJson(R"({"split": {"side": "middle"}})", read, extras, error));
    EXPECT_NE(error.find("split.side"), std::string::npos) << error;
    // A record that names no side is the left side's, and is written back as one (a fuzzed file
    // once read with an empty side, which its own written form then refused).
    ASSERT_TRUE(settingsFromJson(R"({"split": {"divider": 0}})", read, extras, error)) << error;
    ASSERT_TRUE(extras.split.has_value());
    EXPECT_EQ(extras.split->side, "left");
    file.split = extras.split;
    SettingsJsonExtras again;
    ASSERT_TRUE(settingsFromJson(settingsToJson(s, "", file), read, again, error)) << error;
    EXPECT_EQ(again.split, extras.split);
}

TEST(SettingsFiles, CameraBookmarksRoundTripAndBadOnesAreRefused) {
    SettingsFileExtras file;
    Camera c;
    c.position = {0.1f, 0.2f, -2.5f};
    c.yawDegrees = 12.5f;
    c.pitchDegrees = -3.0f;
    c.verticalFovDegrees = 40.0f;
    file.bookmarks.slots[0] = c;
    file.bookmarks.slots[8] = Camera();
    const std::string text = settingsToJson(RenderSettings(), "cornell", file);
    RenderSettings read;
    SettingsJsonExtras extras;
    std::string error;
    ASSERT_TRUE(settingsFromJson(text, read, extras, error)) << error;
    EXPECT_EQ(extras.bookmarks, file.bookmarks);
    EXPECT_FALSE(extras.bookmarks.slots[4].has_value());
    // Without any, no key is written.
    EXPECT_EQ(settingsToJson(RenderSettings(), "cornell", SettingsFileExtras{}).find("bookmarks"),
              std::string::npos);
    EXPECT_FALSE(settingsFromJson(R"({"bookmarks": [null]})", read, extras, error));
    EXPECT_NE(error.find("bookmarks"), std::string::npos) << error;
    EXPECT_FALSE(settingsFromJson(
        R"({"bookmarks": [{"fov": 200}, null, null, null, null, null, null, null, null]})", read,
        extras, error));
    EXPECT_NE(error.find("bookmarks[0]"), std::string::npos) << error;
}

using test::labBox;
using test::waitFinal;

std::vector<uint8_t> displayed(const LoadedScene& loaded, const RenderSettings& settings) {
    const Framebuffer image = render(loaded.scene, loaded.bvh, settings);
    std::vector<uint8_t> bgra(4 * image.pixels.size());
    toRgba8(image.pixels, 1.0f, settings.display, settings.exposure, bgra, PixelOrder::Bgra);
    return bgra;
}

TEST(SplitView, TheWorkerConvergesBothSidesAndMovingTheDividerKeepsTheirSamples) {
    const auto box = labBox();
    RenderWorker worker;
    RenderSettings left;
    left.width = 48;
    left.height = 36;
    left.samplesPerPixel = 3;
    left.threads = 2;
    RenderJob job{box, left};
    job.compare = otherIntegrator(left);
    job.divider = 0.5f;
    const ShownImage first = waitFinal(worker, worker.submit(job));
    ASSERT_TRUE(first.compare.has_value());
    EXPECT_EQ(first.settings.samplesPerPixel, 3);
    EXPECT_EQ(first.compare->samplesPerPixel, 3);
    std::vector<uint8_t> expected(first.bgra.pixels.size());
    composeSplit(displayed(*box, left), displayed(*box, *job.compare), 48, 36, 0.5f, expected);
    EXPECT_EQ(first.bgra.pixels, expected);

    // Moving the divider only recomposes: no pass, the same samples on both sides.
    const PassTotals before = worker.totals();
    job.divider = 0.25f;
    const ShownImage moved = waitFinal(worker, worker.submit(job));
    EXPECT_EQ(worker.totals().passes.count, before.passes.count);
    composeSplit(displayed(*box, left), displayed(*box, *job.compare), 48, 36, 0.25f, expected);
    EXPECT_EQ(moved.bgra.pixels, expected);
    EXPECT_EQ(moved.divider, 0.25f);
}

} // namespace
} // namespace raylab::viewer
