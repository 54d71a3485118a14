// RedrawSchedule: frames only when wanted, paced, with their response times.

#include "redraw_schedule.h"

#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

using TimePoint = RedrawSchedule::TimePoint;
using Ms = std::chrono::milliseconds;

const TimePoint kStart = TimePoint() + std::chrono::hours(1);

// Starts and shows a frame at `at` (which must be due); returns its response in milliseconds.
double drawAt(RedrawSchedule& schedule, TimePoint at) {
    EXPECT_TRUE(schedule.due(at));
    schedule.frameStarted(at);
    return schedule.frameShown(at) * 1000.0;
}

TEST(ViewerRedrawSchedule, NothingWantedNothingDue) {
    RedrawSchedule schedule(60.0);
    EXPECT_FALSE(schedule.due(kStart));
    EXPECT_EQ(schedule.wakeAt(), TimePoint::max());
    schedule.want(kStart);
    EXPECT_TRUE(schedule.due(kStart));
    EXPECT_LT(drawAt(schedule, kStart), 0.0); // the first frame has no response time
    EXPECT_FALSE(schedule.due(kStart + Ms(500)));
    EXPECT_EQ(schedule.wakeAt(), TimePoint::max());
}

TEST(ViewerRedrawSchedule, FramesArePacedAndRespondFromTheirWant) {
    RedrawSchedule schedule(50.0); // 20 ms slots
    schedule.want(kStart);
    drawAt(schedule, kStart);
    // Wanted 5 ms later: waits for the slot at 20 ms, so it answers 15 ms after the want.
    schedule.want(kStart + Ms(5));
    EXPECT_FALSE(schedule.due(kStart + Ms(5)));
    EXPECT_EQ(schedule.wakeAt(), kStart + Ms(20));
    EXPECT_NEAR(drawAt(schedule, kStart + Ms(20)), 15.0, 1e-6);
    // Wanted long after the last slot: drawn at once, and the next slot is one period later.
    schedule.want(kStart + Ms(1000));
    EXPECT_NEAR(drawAt(schedule, kStart + Ms(1003)), 3.0, 1e-6);
    schedule.want(kStart + Ms(1004));
    EXPECT_FALSE(schedule.due(kStart + Ms(1010)));
    EXPECT_TRUE(schedule.due(kStart + Ms(1023)));
}

TEST(ViewerRedrawSchedule, SeveralFramesAfterAnEvent) {
    RedrawSchedule schedule(50.0);
    schedule.want(kStart, 3);
    drawAt(schedule, kStart);
    // The two frames still wanted follow at the frame rate, each wanted from the previous swap.
    EXPECT_EQ(schedule.wakeAt(), kStart + Ms(20));
    EXPECT_NEAR(drawAt(schedule, kStart + Ms(20)), 20.0, 1e-6);
    EXPECT_NEAR(drawAt(schedule, kStart + Ms(40)), 20.0, 1e-6);
    EXPECT_FALSE(schedule.due(kStart + Ms(60)));
    // A want while frames are wanted keeps the larger count, not the sum.
    schedule.want(kStart + Ms(100), 2);
    schedule.want(kStart + Ms(101), 1);
    drawAt(schedule, kStart + Ms(101));
    drawAt(schedule, kStart + Ms(121));
    EXPECT_FALSE(schedule.due(kStart + Ms(141)));
}

TEST(ViewerRedrawSchedule, WantAtWaitsForItsTime) {
    RedrawSchedule schedule(50.0);
    schedule.want(kStart);
    drawAt(schedule, kStart);
    schedule.wantAt(kStart + Ms(100));
    schedule.wantAt(kStart + Ms(300)); // the earliest wins
    EXPECT_EQ(schedule.wakeAt(), kStart + Ms(100));
    EXPECT_FALSE(schedule.due(kStart + Ms(99)));
    EXPECT_NEAR(drawAt(schedule, kStart + Ms(100)), 0.0, 1e-6);
    EXPECT_EQ(schedule.wakeAt(), TimePoint::max());
    // A wantAt before the next slot waits for the slot.
    schedule.wantAt(kStart + Ms(105));
    EXPECT_EQ(schedule.wakeAt(), kStart + Ms(120));
}

TEST(ViewerRedrawSchedule, ContinuousDrawsEverySlotAndRespondsSwapToSwap) {
    RedrawSchedule schedule(50.0, true);
    EXPECT_TRUE(schedule.due(kStart));
    drawAt(schedule, kStart);
    EXPECT_EQ(schedule.wakeAt(), kStart + Ms(20));
    EXPECT_FALSE(schedule.due(kStart + Ms(19)));
    schedule.frameStarted(kStart + Ms(25));
    EXPECT_NEAR(schedule.frameShown(kStart + Ms(31)) * 1000.0, 31.0, 1e-6);
}

TEST(ViewerRedrawSchedule, ResumeCountsNoTimeAway) {
    for (const bool continuous : {false, true}) {
        RedrawSchedule schedule(50.0, continuous);
        schedule.want(kStart);
        drawAt(schedule, kStart);
        schedule.want(kStart + Ms(10)); // wanted, then minimised until 5 s
        schedule.resume(kStart + Ms(5000));
        EXPECT_NEAR(drawAt(schedule, kStart + Ms(5002)), 2.0, 1e-6) << continuous;
    }
}

} // namespace
} // namespace raylab::viewer
