#pragma once
// How far the navigation keys move the camera and the light, in steps (navigation.h), frame by
// frame. A press moves one step at once, so a tap moves exactly one. A key still held
// kHoldDelaySeconds after its press then moves continuously, kHeldStepsPerSecond, until its
// release: a key held for h seconds (h >= the delay) moves 1 + kHeldStepsPerSecond * (h - delay)
// steps in all, whatever the frame times, as long as no frame is longer than kMaxFrameSeconds.
// Keys held together move together (each by its own steps).
//
// Times are steady_clock time points, given by the caller (no clock is read here); they must not
// go back. No GLFW or ImGui calls: the window glue is input.h and viewer_input.cpp.

#include "navigation.h"

#include <array>
#include <chrono>
#include <cstddef>
#include <optional>
#include <vector>

namespace raylab::viewer {

// From the press to the start of the continuous motion (seconds); a shorter hold is a tap.
inline constexpr double kHoldDelaySeconds = 0.25;
// The continuous motion's speed (steps per second): that of X's key repeat (25 a second).
inline constexpr double kHeldStepsPerSecond = 25.0;
// The most time one frame counts (seconds): after a stall, held keys move as if this much passed.
inline constexpr double kMaxFrameSeconds = 0.1;

// One action's motion in one frame.
struct NavMotion {
    NavAction action = NavAction::CameraForward;
    float steps = 0.0f; // > 0; fractional while held
};

class HeldKeys {
public:
    using Clock = std::chrono::steady_clock;
    using TimePoint = Clock::time_point;

    // The key of `action` went down at `when`: one step (in the next advance), continuous motion
    // from the delay on.
    // A press of a key held already counts as its release and a new press.
    void press(NavAction action, TimePoint when);
    // The key of `action` went up at `when`: its motion stops there. Ignored when not held.
    void release(NavAction action, TimePoint when);
    // Every held key goes up at `when` (the window lost focus, or the panel took the keyboard).
    void releaseAll(TimePoint when);
    // Whether any key is held (each frame then moves something, once past the delay).
    bool anyHeld() const;

    // The motion of a frame at `now`, in NavAction order, only actions that move: the steps of
    // the presses since the last call, plus, for each key, kHeldStepsPerSecond times the time it
    // was held past its delay within this frame's interval. The interval starts at the previous
    // call's `now` (the first call counts no held time) and lasts now minus that, at most
    // kMaxFrameSeconds.
    std::vector<NavMotion> advance(TimePoint now);

private:
    // NavAction's count: LightUp is its last value.
    static constexpr std::size_t kActions = static_cast<std::size_t>(NavAction::LightUp) + 1;

    struct Key {
        bool held = false;
        TimePoint pressedAt{};
        double steps = 0.0; // counted since the last advance: presses and time held up to a release
    };

    // Steps of a key pressed at `pressedAt` for the time it was held past the delay within the
    // current frame's interval and before `until`.
    double heldSteps(TimePoint pressedAt, TimePoint until) const;

    std::array<Key, kActions> keys_{};
    std::optional<TimePoint> lastFrame_; // the previous advance's `now`
};

} // namespace raylab::viewer
