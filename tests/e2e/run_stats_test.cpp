// RunStats: the --stats file's numbers and their units.

#include "run_stats.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace raylab::viewer {
namespace {

TEST(ViewerRunStats, TallyKeepsCountSumMinMax) {
    Tally tally;
    EXPECT_EQ(tally.mean(), 0.0);
    tally.add(0.5);
    tally.add(0.25);
    tally.add(2.0);
    EXPECT_EQ(tally.count, 3u);
    EXPECT_DOUBLE_EQ(tally.mean(), 2.75 / 3.0);
    EXPECT_EQ(tally.min, 0.25);
    EXPECT_EQ(tally.max, 2.0);
}

TEST(ViewerRunStats, JsonHasRatesInFramesPerSecondAndTimesInMilliseconds) {
    RunStats stats;
    stats.framesShown = 61;
    stats.shownSeconds = 2.0;
    stats.frameResponses.add(0.02);
    stats.frameResponses.add(0.04);
    stats.drawTimes.add(0.003);
    stats.drawTimes.add(0.005);
    stats.uploads.add(0.001);
    stats.uploads.add(0.001);
    stats.uploads.add(0.001);
    stats.slowFrames = 1;
    stats.viewsShown = 2;
    stats.tracer.passes.add(0.010);
    stats.tracer.passes.add(0.030);
    stats.tracer.cancelled = 4;
    stats.width = 640;
    stats.height = 360;
    stats.samples = 2;
    stats.scene = "a \"quoted\" path.obj";
    stats.triangles = 30;
    const nlohmann::json json = nlohmann::json::parse(runStatsJson(stats));
    EXPECT_EQ(json["redraw"], "on demand");
    EXPECT_EQ(json["frames_shown"], 61);
    EXPECT_DOUBLE_EQ(json["window_fps"].get<double>(), 30.0);
    EXPECT_EQ(json["pictures_shown"], 3);
    EXPECT_DOUBLE_EQ(json["pictures_per_second"].get<double>(), 1.5);
    EXPECT_EQ(json["views_shown"], 2);
    EXPECT_DOUBLE_EQ(json["views_per_second"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(json["frame_ms"]["max"].get<double>(), 40.0);
    EXPECT_DOUBLE_EQ(json["draw_ms"]["mean"].get<double>(), 4.0);
    EXPECT_EQ(json["frames_over_33ms"], 1);
    EXPECT_EQ(json["passes"], 2);
    EXPECT_DOUBLE_EQ(json["pass_ms"]["mean"].get<double>(), 20.0);
    EXPECT_DOUBLE_EQ(json["pass_ms"]["min"].get<double>(), 10.0);
    EXPECT_EQ(json["previews"], 0);
    EXPECT_EQ(json["cancelled_passes"], 4);
    EXPECT_EQ(json["render_width"], 640);
    EXPECT_EQ(json["render_height"], 360);
    EXPECT_EQ(json["scene"], "a \"quoted\" path.obj");
}

TEST(ViewerRunStats, ReadoutsAreWrittenOnlyWhenKnownWithTheirFloatsExact) {
    RunStats stats;
    EXPECT_FALSE(nlohmann::json::parse(runStatsJson(stats)).contains("hover"));
    EXPECT_FALSE(nlohmann::json::parse(runStatsJson(stats)).contains("rectangle"));
    stats.hover = PixelReadout{12, 34, {0.1f, 1.0f / 3.0f, 2.5f}, {26, 85, 255}};
    RectangleMean mean;
    mean.rectangle = {1, 2, 3, 5};
    mean.pixels = 12;
    mean.mean = {0.25, 0.125, 1.0 / 3.0};
    stats.rectangle = mean;
    const nlohmann::json json = nlohmann::json::parse(runStatsJson(stats));
    EXPECT_EQ(json["hover"]["pixel"], nlohmann::json::array({12, 34}));
    // The float read back as a double is the float itself.
    EXPECT_EQ(static_cast<float>(json["hover"]["linear"][1].get<double>()), 1.0f / 3.0f);
    EXPECT_EQ(json["hover"]["linear"][1].get<double>(), static_cast<double>(1.0f / 3.0f));
    EXPECT_EQ(json["hover"]["display"], nlohmann::json::array({26, 85, 255}));
    EXPECT_EQ(json["rectangle"]["from"], nlohmann::json::array({1, 2}));
    EXPECT_EQ(json["rectangle"]["to"], nlohmann::json::array({3, 5}));
    EXPECT_EQ(json["rectangle"]["pixels"], 12);
    EXPECT_EQ(json["rectangle"]["mean"][2].get<double>(), 1.0 / 3.0);
}

} // namespace
} // namespace raylab::viewer
