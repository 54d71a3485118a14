#pragma once
// When the window draws a frame. With a software GL driver (llvmpipe) every frame costs CPU that
// the tracer shares, so the window draws only when a frame is wanted: a new picture of the
// tracer, an input or window event, and the few frames after one that Dear ImGui needs to settle
// (hover, activation). Frames are paced to at most framesPerSecond: a frame wanted sooner than
// one period after the previous one waits for its slot (slots are one period apart, on a grid
// that restarts after an idle gap). In continuous mode (scripted runs) every
// slot draws a frame, as a game loop would.
//
// Times are steady_clock time points, given by the caller (no clock is read here).

#include <chrono>

namespace raylab::viewer {

class RedrawSchedule {
public:
    using Clock = std::chrono::steady_clock;
    using TimePoint = Clock::time_point;

    // framesPerSecond > 0. continuous: draw every slot, whether wanted or not.
    explicit RedrawSchedule(double framesPerSecond, bool continuous = false);

    // The next `frames` frames (at least 1) are wanted, from `now` on.
    void want(TimePoint now, int frames = 1);
    // One frame is wanted at `when` (not before); a later call keeps the earliest such time.
    void wantAt(TimePoint when);

    // The window is back (restored after being minimised) at `now`: a frame is wanted, and the
    // time away counts in no response (what was wanted before counts as wanted from now).
    void resume(TimePoint now);

    // Whether a frame should start at `now`: one is wanted and its slot has come.
    bool due(TimePoint now) const;
    // The earliest time at which due() can become true without another want: the next slot
    // when a frame is wanted, the wantAt time (or the slot after it), TimePoint::max() when none.
    TimePoint wakeAt() const;

    // A frame starts at `now` (due(now) held): it takes one wanted frame and sets the next slot.
    void frameStarted(TimePoint now);
    // The frame started last was shown (swapped) at `now`. Returns its response time in seconds:
    // from when it was first wanted (not before the previous swap) to now. In continuous mode
    // that is the time since the previous swap. Returns a negative value for the first frame.
    double frameShown(TimePoint now);

private:
    Clock::duration period_;
    bool continuous_;
    int framesWanted_ = 0;
    TimePoint wantedSince_{};               // when the first of framesWanted_ became wanted
    TimePoint wantedAt_ = TimePoint::max(); // a frame wanted at this time; max: none
    TimePoint nextSlot_{};                  // the earliest start of the next frame
    TimePoint startedWantedSince_{};        // the frame in flight: when it became wanted
    TimePoint lastShown_{};
    bool shownOnce_ = false;
};

} // namespace raylab::viewer
