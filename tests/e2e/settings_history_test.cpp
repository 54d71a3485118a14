// Undo and redo in steps a person recognises: changes settle into steps, undo and redo walk them,
// a new change forgets what was undone, the render size is not a step.

#include "settings_history.h"

#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

using Clock = SettingsHistory::Clock;
using std::chrono::milliseconds;

TEST(SettingsHistory, ADragIsOneStepOnceItHoldsStill) {
    RenderSettings s;
    SettingsHistory history(s);
    const Clock::time_point t0{};
    // A slider dragged over many frames: values change every 16 ms.
    for (int i = 1; i <= 30; ++i) {
        s.light.intensity = 14.0f + static_cast<float>(i);
        history.observe(s, t0 + milliseconds(16 * i));
    }
    EXPECT_EQ(history.steps(), 1u); // not settled yet
    history.observe(s, t0 + milliseconds(16 * 30 + 500));
    EXPECT_EQ(history.steps(), 2u); // the whole drag, one step

    RenderSettings current = s;
    ASSERT_TRUE(history.undo(current));
    EXPECT_EQ(current.light.intensity, 14.0f);
    EXPECT_FALSE(history.undo(current)); // nothing before the start
    ASSERT_TRUE(history.redo(current));
    EXPECT_EQ(current.light.intensity, 44.0f);
    EXPECT_FALSE(history.redo(current));
}

TEST(SettingsHistory, UndoOfAnUnsettledChangeReturnsToTheLastStepAndRedoBringsItBack) {
    RenderSettings s;
    SettingsHistory history(s);
    s.shadowEpsilon = 0.0f;
    history.observe(s, Clock::time_point{} + milliseconds(5));
    RenderSettings current = s;
    ASSERT_TRUE(history.undo(current));
    EXPECT_EQ(current.shadowEpsilon, RenderSettings().shadowEpsilon);
    ASSERT_TRUE(history.redo(current));
    EXPECT_EQ(current.shadowEpsilon, 0.0f);
}

TEST(SettingsHistory, ANewChangeForgetsTheUndoneStepsAndTheSizeIsKept) {
    RenderSettings s;
    SettingsHistory history(s);
    Clock::time_point t{};
    const auto settle = [&](const RenderSettings& settings) {
        history.observe(settings, t += milliseconds(10));
        history.observe(settings, t += milliseconds(500));
    };
    s.camera.yawDegrees = 10.0f;
    settle(s);
    s.camera.yawDegrees = 20.0f;
    settle(s);
    ASSERT_EQ(history.steps(), 3u);
    RenderSettings current = s;
    current.width = 123; // the window was resized meanwhile
    ASSERT_TRUE(history.undo(current));
    EXPECT_EQ(current.camera.yawDegrees, 10.0f);
    EXPECT_EQ(current.width, 123);
    // A resize alone is no step.
    current.height = 77;
    settle(current);
    EXPECT_EQ(history.position(), 1u);
    // A new change after an undo forgets the undone yaw of 20.
    current.indirect = false;
    settle(current);
    EXPECT_EQ(history.steps(), 3u);
    EXPECT_FALSE(history.redo(current));
    ASSERT_TRUE(history.undo(current));
    EXPECT_TRUE(current.indirect);
    EXPECT_EQ(current.camera.yawDegrees, 10.0f);
}

} // namespace
} // namespace raylab::viewer
