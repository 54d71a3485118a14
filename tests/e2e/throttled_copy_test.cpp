// ThrottledCopy, as the panel uses it (panel_layer.h): its copy changes at most once a period,
// at once when forced or at the first call; the statistics' copy keeps every value the histories
// recorded meanwhile, and only a new picture (not the window timings) asks to catch up.

#include "core/render_settings.h"
#include "panel_numbers.h"
#include "throttled_copy.h"

#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

using Numbers = ThrottledCopy<PanelNumbers, &PanelNumbers::picture>;
using Settings = ThrottledCopy<RenderSettings>;
using TimePoint = Settings::TimePoint;
using Ms = std::chrono::milliseconds;

const TimePoint kStart = TimePoint{} + std::chrono::hours(1);

RenderSettings movedTo(float z) {
    RenderSettings s;
    s.camera.position.z = z;
    return s;
}

TEST(ViewerThrottledCopy, NumbersChangeAtMostOncePerPeriod) {
    Numbers copy(Ms(250));
    PanelNumbers live;
    live.drawMs.push(4.0f);
    EXPECT_TRUE(copy.follow(live, kStart)); // the first call copies
    EXPECT_FLOAT_EQ(copy.shown().drawMs.latest(), 4.0f);
    for (int frame = 1; frame < 15; ++frame) { // 15 frames at 60 per second: 233 ms
        live.drawMs.push(4.0f + static_cast<float>(frame));
        EXPECT_FALSE(copy.follow(live, kStart + Ms(frame * 1000 / 60)));
        EXPECT_FLOAT_EQ(copy.shown().drawMs.latest(), 4.0f) << "frame " << frame;
    }
    live.drawMs.push(30.0f);
    EXPECT_TRUE(copy.follow(live, kStart + Ms(250)));
    // The copy has every value pushed meanwhile, in order: the plots stay complete.
    EXPECT_FLOAT_EQ(copy.shown().drawMs.latest(), 30.0f);
    const History& shown = copy.shown().drawMs;
    const int oldest = shown.offset();
    EXPECT_FLOAT_EQ(shown.data()[(oldest + shown.size() - 2) % shown.size()], 18.0f);
    EXPECT_FLOAT_EQ(shown.mean(), live.drawMs.mean());
    EXPECT_EQ(copy.shown(), live);
    live.frameMs.push(16.0f);
    EXPECT_FALSE(copy.follow(live, kStart + Ms(499)));
    EXPECT_TRUE(copy.follow(live, kStart + Ms(500)));
    EXPECT_EQ(copy.shown(), live);
}

TEST(ViewerThrottledCopy, NumbersCatchUpWithTheLastPictureOnly) {
    Numbers copy(Ms(250));
    PanelNumbers live;
    // Nothing shown yet: at once (a time already past).
    ASSERT_TRUE(copy.catchUpAt(live).has_value());
    EXPECT_LE(*copy.catchUpAt(live), kStart);
    copy.follow(live, kStart);
    EXPECT_FALSE(copy.catchUpAt(live).has_value());
    // Window timings alone never ask for a frame (each frame drawn changes them).
    live.frameMs.push(16.0f);
    live.drawMs.push(3.0f);
    live.uploadMs = 1.5;
    EXPECT_FALSE(copy.catchUpAt(live).has_value());
    // A new picture does, at the next refresh; then the panel shows it and asks no more.
    live.picture = {1280, 720, 64, false, true, 40.0, 2.5e7};
    ASSERT_TRUE(copy.catchUpAt(live).has_value());
    EXPECT_EQ(*copy.catchUpAt(live), kStart + Ms(250));
    EXPECT_FALSE(copy.follow(live, kStart + Ms(100)));
    EXPECT_EQ(*copy.catchUpAt(live), kStart + Ms(250)) << "a refused follow moves nothing";
    EXPECT_TRUE(copy.follow(live, *copy.catchUpAt(live)));
    EXPECT_EQ(copy.shown().picture, live.picture);
    EXPECT_FALSE(copy.catchUpAt(live).has_value());
    // The next picture: one period after the copy last changed.
    live.picture.samples = 128;
    EXPECT_EQ(*copy.catchUpAt(live), kStart + Ms(500));
}

TEST(ViewerThrottledCopy, SettingsFollowNavigationAtMostOncePerPeriod) {
    Settings copy(Ms(100));
    copy.follow(movedTo(-3.0f), kStart);
    EXPECT_EQ(copy.shown().camera.position.z, -3.0f);
    // The first change after a still period shows at once (a single key press).
    EXPECT_TRUE(copy.follow(movedTo(-2.9f), kStart + Ms(500)));
    EXPECT_EQ(copy.shown().camera.position.z, -2.9f);
    // Changes every frame (60 Hz) for 0.28 s: the copy changes only every 100 ms.
    int changes = 0;
    float last = -2.9f;
    for (int frame = 1; frame <= 17; ++frame) {
        const float z = -2.9f + 0.01f * static_cast<float>(frame);
        copy.follow(movedTo(z), kStart + Ms(500) + Ms(frame * 1000 / 60));
        if (copy.shown().camera.position.z != last) {
            ++changes;
            last = copy.shown().camera.position.z;
            EXPECT_EQ(last, z) << "a refresh copies the live settings";
        }
    }
    EXPECT_EQ(changes, 2); // at 500 + 100 ms and at 500 + 200 ms (frames 6 and 12)
    // Stale now: it catches up one period after its last change.
    const RenderSettings live = movedTo(-2.72f);
    ASSERT_TRUE(copy.catchUpAt(live).has_value());
    EXPECT_EQ(*copy.catchUpAt(live), kStart + Ms(500) + Ms(12 * 1000 / 60) + Ms(100));
    copy.follow(live, *copy.catchUpAt(live));
    EXPECT_EQ(copy.shown().camera.position.z, -2.72f);
    EXPECT_FALSE(copy.catchUpAt(live).has_value());
}

TEST(ViewerThrottledCopy, ThePeriodCountsFromTheLastChange) {
    Settings copy(Ms(100));
    copy.follow(movedTo(-3.0f), kStart);
    // Frames of an unchanged value (a picture arriving, a hover) do not restart the period...
    EXPECT_FALSE(copy.follow(movedTo(-3.0f), kStart + Ms(60)));
    EXPECT_TRUE(copy.follow(movedTo(-3.0f), kStart + Ms(120)));
    EXPECT_TRUE(copy.follow(movedTo(-3.0f), kStart + Ms(170), true));
    // ... so a change after them shows at once.
    EXPECT_TRUE(copy.follow(movedTo(-2.0f), kStart + Ms(180)));
    EXPECT_EQ(copy.shown().camera.position.z, -2.0f);
    EXPECT_FALSE(copy.follow(movedTo(-1.0f), kStart + Ms(279)));
    EXPECT_EQ(copy.shown().camera.position.z, -2.0f);
}

TEST(ViewerThrottledCopy, ForcedCopiesFollowAtOnce) {
    Settings copy(Ms(100));
    copy.follow(movedTo(-3.0f), kStart);
    EXPECT_FALSE(copy.follow(movedTo(-2.9f), kStart + Ms(17)));
    EXPECT_EQ(copy.shown().camera.position.z, -3.0f);
    EXPECT_TRUE(copy.follow(movedTo(-2.7f), kStart + Ms(34), true));
    EXPECT_EQ(copy.shown().camera.position.z, -2.7f);
    EXPECT_TRUE(copy.follow(movedTo(-2.6f), kStart + Ms(51), true));
    EXPECT_EQ(copy.shown().camera.position.z, -2.6f);
    // A forced change restarts the period like any other.
    EXPECT_EQ(*copy.catchUpAt(movedTo(-2.5f)), kStart + Ms(151));
}

TEST(ViewerThrottledCopy, EverySettingCounts) {
    Settings copy(Ms(100));
    RenderSettings live;
    copy.follow(live, kStart);
    live.shadowEpsilon = 0.002f;
    ASSERT_TRUE(copy.catchUpAt(live).has_value());
    live = RenderSettings{};
    live.light.color.y = 0.5f;
    EXPECT_TRUE(copy.catchUpAt(live).has_value());
    EXPECT_FALSE(copy.catchUpAt(RenderSettings{}).has_value());
}

} // namespace
} // namespace raylab::viewer
