// HeldKeys: a tap moves one step, a held key moves smoothly after the hold delay, by the time it
// is held and not by the number of frames.

#include "held_keys.h"

#include <gtest/gtest.h>
#include <map>
#include <vector>

namespace raylab::viewer {
namespace {

using TimePoint = HeldKeys::TimePoint;
using Ms = std::chrono::milliseconds;
using Us = std::chrono::microseconds;

const TimePoint kStart = TimePoint() + std::chrono::hours(1);

// A key going down or up, handed to HeldKeys by the first frame at or after `when`.
struct KeyChange {
    NavAction action;
    bool down;
    TimePoint when;
};

using Totals = std::map<NavAction, double>; // steps moved, per action

// Frames from `start` until `end` (inclusive of the first frame at or past it), one after the
// other by the durations in `pattern`, repeated.
std::vector<TimePoint> frames(TimePoint start, TimePoint end, const std::vector<Us>& pattern) {
    std::vector<TimePoint> times{start};
    for (std::size_t i = 0; times.back() < end; ++i) {
        times.push_back(times.back() + pattern[i % pattern.size()]);
    }
    return times;
}

// Runs `keys` through the frames at `times`, as the viewer does: each frame hands over the
// changes that happened up to its time, then advances. Returns the steps moved per action.
Totals run(HeldKeys& keys, const std::vector<TimePoint>& times,
           const std::vector<KeyChange>& changes) {
    Totals totals;
    std::size_t next = 0;
    for (const TimePoint now : times) {
        for (; next < changes.size() && changes[next].when <= now; ++next) {
            const KeyChange& change = changes[next];
            if (change.down) {
                keys.press(change.action, change.when);
            } else {
                keys.release(change.action, change.when);
            }
        }
        for (const NavMotion& motion : keys.advance(now)) {
            EXPECT_GT(motion.steps, 0.0f);
            totals[motion.action] += motion.steps;
        }
    }
    return totals;
}

// Up held for `holdSeconds` from 3 ms into frames of the given durations; the steps it moved.
double upHeldFor(double holdSeconds, const std::vector<Us>& pattern) {
    HeldKeys keys;
    const TimePoint press = kStart + Ms(3);
    const TimePoint release =
        press + std::chrono::duration_cast<Us>(std::chrono::duration<double>(holdSeconds));
    const Totals totals =
        run(keys, frames(kStart, release + Ms(500), pattern),
            {{NavAction::CameraForward, true, press}, {NavAction::CameraForward, false, release}});
    EXPECT_EQ(totals.size(), 1u);
    EXPECT_FALSE(keys.anyHeld());
    return totals.count(NavAction::CameraForward) ? totals.at(NavAction::CameraForward) : 0.0;
}

TEST(ViewerHeldKeys, TapMovesExactlyOneStepAndNothingAfterTheRelease) {
    HeldKeys keys;
    EXPECT_TRUE(keys.advance(kStart).empty());
    keys.press(NavAction::CameraForward, kStart + Ms(5));
    EXPECT_TRUE(keys.anyHeld());
    const std::vector<NavMotion> first = keys.advance(kStart + Ms(16));
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].action, NavAction::CameraForward);
    EXPECT_EQ(first[0].steps, 1.0f); // exactly one, as the lab's key press
    keys.release(NavAction::CameraForward, kStart + Ms(60));
    EXPECT_FALSE(keys.anyHeld());
    for (int frame = 2; frame < 120; ++frame) {
        EXPECT_TRUE(keys.advance(kStart + Ms(16 * frame)).empty()) << "frame " << frame;
    }
}

TEST(ViewerHeldKeys, PressAndReleaseWithinOneFrameStillMoveOneStep) {
    HeldKeys keys;
    keys.advance(kStart);
    keys.press(NavAction::LightUp, kStart + Ms(2));
    keys.release(NavAction::LightUp, kStart + Ms(4));
    const std::vector<NavMotion> motion = keys.advance(kStart + Ms(16));
    ASSERT_EQ(motion.size(), 1u);
    EXPECT_EQ(motion[0].action, NavAction::LightUp);
    EXPECT_EQ(motion[0].steps, 1.0f);
}

TEST(ViewerHeldKeys, HoldMovesByTheTimeHeldAt60Hz) {
    // 1 + 25 * (1.25 - 0.25) = 26 steps.
    EXPECT_NEAR(upHeldFor(1.25, {Us(16667)}), 26.0, 1e-4);
}

TEST(ViewerHeldKeys, HoldMovesByTheTimeHeldWithIrregularFrames) {
    EXPECT_NEAR(upHeldFor(1.25, {Ms(7), Ms(23), Ms(41)}), 26.0, 1e-4);
    EXPECT_NEAR(upHeldFor(2.0, {Ms(41), Ms(7), Ms(23), Ms(23)}), 1.0 + 25.0 * 1.75, 1e-4);
}

TEST(ViewerHeldKeys, NoMotionDuringTheHoldDelay) {
    EXPECT_EQ(upHeldFor(0.249, {Ms(7), Ms(23), Ms(41)}), 1.0);
    HeldKeys keys;
    const TimePoint press = kStart + Ms(1);
    const Totals during =
        run(keys, frames(kStart, press + Ms(249), {Ms(10)}), {{NavAction::TurnLeft, true, press}});
    EXPECT_EQ(during.at(NavAction::TurnLeft), 1.0);
    EXPECT_TRUE(keys.anyHeld());
    // The last frame was at press + 249 ms; the next, at press + 300 ms, moves for 50 ms.
    const std::vector<NavMotion> after = keys.advance(press + Ms(300));
    ASSERT_EQ(after.size(), 1u);
    EXPECT_NEAR(after[0].steps, 25.0 * 0.050, 1e-5);
}

TEST(ViewerHeldKeys, AStalledFrameMovesAtMostItsClampedTime) {
    HeldKeys keys;
    keys.advance(kStart);
    keys.press(NavAction::CameraBack, kStart);
    keys.advance(kStart + Ms(500)); // one step, past the delay but counting 0.1 s from kStart
    const std::vector<NavMotion> stalled = keys.advance(kStart + Ms(1500));
    ASSERT_EQ(stalled.size(), 1u);
    EXPECT_NEAR(stalled[0].steps, kHeldStepsPerSecond * kMaxFrameSeconds, 1e-5);
    const std::vector<NavMotion> normal = keys.advance(kStart + Ms(1520));
    ASSERT_EQ(normal.size(), 1u);
    EXPECT_NEAR(normal[0].steps, 25.0 * 0.020, 1e-5);
}

TEST(ViewerHeldKeys, ReleaseWithinAFrameStopsTheMotionAtTheRelease) {
    HeldKeys keys;
    keys.advance(kStart);
    keys.press(NavAction::LightLeft, kStart);
    keys.advance(kStart + Ms(300));
    keys.advance(kStart + Ms(316));
    keys.release(NavAction::LightLeft, kStart + Ms(326));
    const std::vector<NavMotion> last = keys.advance(kStart + Ms(332));
    ASSERT_EQ(last.size(), 1u);
    EXPECT_NEAR(last[0].steps, 25.0 * 0.010, 1e-5);
    EXPECT_TRUE(keys.advance(kStart + Ms(348)).empty());
}

TEST(ViewerHeldKeys, TwoHeldKeysMoveTogether) {
    HeldKeys keys;
    const TimePoint up = kStart + Ms(5);
    const TimePoint left = kStart + Ms(505);
    const Totals totals = run(keys, frames(kStart, kStart + Ms(2500), {Ms(7), Ms(23), Ms(41)}),
                              {{NavAction::CameraForward, true, up},
                               {NavAction::TurnLeft, true, left},
                               {NavAction::TurnLeft, false, left + Ms(1000)},
                               {NavAction::CameraForward, false, up + Ms(1500)}});
    ASSERT_EQ(totals.size(), 2u);
    EXPECT_NEAR(totals.at(NavAction::CameraForward), 1.0 + 25.0 * 1.25, 1e-4);
    EXPECT_NEAR(totals.at(NavAction::TurnLeft), 1.0 + 25.0 * 0.75, 1e-4);
    // While both are held, one frame moves both.
    HeldKeys both;
    both.advance(kStart);
    both.press(NavAction::CameraForward, kStart);
    both.press(NavAction::LightDown, kStart);
    both.advance(kStart + Ms(300));
    const std::vector<NavMotion> frame = both.advance(kStart + Ms(316));
    ASSERT_EQ(frame.size(), 2u);
    EXPECT_EQ(frame[0].action, NavAction::CameraForward);
    EXPECT_EQ(frame[1].action, NavAction::LightDown);
    EXPECT_NEAR(frame[0].steps, 25.0 * 0.016, 1e-5);
    EXPECT_NEAR(frame[1].steps, 25.0 * 0.016, 1e-5);
}

TEST(ViewerHeldKeys, ReleaseAllStopsEveryKey) {
    HeldKeys keys;
    keys.advance(kStart);
    keys.press(NavAction::CameraForward, kStart);
    keys.press(NavAction::TurnRight, kStart);
    keys.advance(kStart + Ms(300));
    keys.releaseAll(kStart + Ms(310)); // the window lost the focus; no releases came
    EXPECT_FALSE(keys.anyHeld());
    const std::vector<NavMotion> last = keys.advance(kStart + Ms(316));
    ASSERT_EQ(last.size(), 2u);
    EXPECT_NEAR(last[0].steps, 25.0 * 0.010, 1e-5);
    EXPECT_NEAR(last[1].steps, 25.0 * 0.010, 1e-5);
    EXPECT_TRUE(keys.advance(kStart + Ms(332)).empty());
    EXPECT_TRUE(keys.advance(kStart + Ms(900)).empty());
    // A release arriving late, after the focus loss, changes nothing.
    keys.release(NavAction::CameraForward, kStart + Ms(905));
    EXPECT_TRUE(keys.advance(kStart + Ms(916)).empty());
}

TEST(ViewerHeldKeys, APressOfAHeldKeyStartsItsHoldAgain) {
    HeldKeys keys;
    keys.advance(kStart);
    keys.press(NavAction::CameraForward, kStart);
    keys.advance(kStart + Ms(300));
    keys.press(NavAction::CameraForward, kStart + Ms(310)); // its release was lost
    const std::vector<NavMotion> frame = keys.advance(kStart + Ms(316));
    ASSERT_EQ(frame.size(), 1u);
    EXPECT_NEAR(frame[0].steps, 1.0 + 25.0 * 0.010, 1e-5);
    keys.advance(kStart + Ms(500)); // within the new press's delay
    EXPECT_TRUE(keys.advance(kStart + Ms(550)).empty());
}

} // namespace
} // namespace raylab::viewer
