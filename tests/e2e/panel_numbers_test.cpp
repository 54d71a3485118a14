// PanelNumbersRefresh: the panel's statistics change at most every period, the histories behind
// them record every value, and the last picture's numbers are caught up.

#include "panel_numbers.h"

#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

using TimePoint = PanelNumbersRefresh::TimePoint;
using Ms = std::chrono::milliseconds;

const TimePoint kStart = TimePoint() + std::chrono::hours(1);

TEST(ViewerPanelNumbers, CopiesAtMostOncePerPeriod) {
    PanelNumbersRefresh refresh(0.25);
    PanelNumbers live;
    live.drawMs.push(4.0f);
    EXPECT_TRUE(refresh.update(live, kStart)); // the first call copies
    EXPECT_FLOAT_EQ(refresh.shown().drawMs.latest(), 4.0f);
    for (int frame = 1; frame < 15; ++frame) { // 15 frames at 60 per second: 233 ms
        live.drawMs.push(4.0f + static_cast<float>(frame));
        EXPECT_FALSE(refresh.update(live, kStart + Ms(frame * 1000 / 60)));
        EXPECT_FLOAT_EQ(refresh.shown().drawMs.latest(), 4.0f) << "frame " << frame;
    }
    live.drawMs.push(30.0f);
    EXPECT_TRUE(refresh.update(live, kStart + Ms(250)));
    // The copy has every value pushed meanwhile, in order: the plots stay complete.
    EXPECT_FLOAT_EQ(refresh.shown().drawMs.latest(), 30.0f);
    const History& shown = refresh.shown().drawMs;
    const int oldest = shown.offset();
    EXPECT_FLOAT_EQ(shown.data()[(oldest + shown.size() - 2) % shown.size()], 18.0f);
    EXPECT_FLOAT_EQ(shown.mean(), live.drawMs.mean());
    EXPECT_FALSE(refresh.update(live, kStart + Ms(499)));
    EXPECT_TRUE(refresh.update(live, kStart + Ms(500)));
}

TEST(ViewerPanelNumbers, CatchesUpWithTheLastPictureOnly) {
    PanelNumbersRefresh refresh(0.25);
    PanelNumbers live;
    EXPECT_TRUE(refresh.catchUpAt(live).has_value()); // nothing shown yet: at once
    refresh.update(live, kStart);
    EXPECT_FALSE(refresh.catchUpAt(live).has_value());
    // Window timings alone never ask for a frame (each frame drawn changes them).
    live.frameMs.push(16.0f);
    live.drawMs.push(3.0f);
    EXPECT_FALSE(refresh.catchUpAt(live).has_value());
    // A new picture does, at the next refresh; then the panel shows it and asks no more.
    live.picture = {1280, 720, 64, false, true, 40.0, 2.5e7};
    ASSERT_TRUE(refresh.catchUpAt(live).has_value());
    EXPECT_EQ(*refresh.catchUpAt(live), kStart + Ms(250));
    EXPECT_FALSE(refresh.update(live, kStart + Ms(100)));
    EXPECT_TRUE(refresh.update(live, *refresh.catchUpAt(live)));
    EXPECT_EQ(refresh.shown().picture, live.picture);
    EXPECT_FALSE(refresh.catchUpAt(live).has_value());
}

} // namespace
} // namespace raylab::viewer
