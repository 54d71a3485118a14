#pragma once
// --replay FILE.json: a recorded session (io/session_recording.h) played back frame by frame.
// The window calls advance() once for each frame it shows while the replay may go on; the
// replay then applies every event recorded up to its frame. At a screenshot it stops: the
// window renders the state in force to the screenshot's samples exactly (pictures are exact
// sums, so its bytes are the recording's), saves it, says screenshotTaken(), and the replay goes
// on from the same frame. Waiting for a picture or a scene load does not count frames.

#include "io/session_recording.h"

#include <cstddef>
#include <optional>

namespace raylab::viewer {

class SessionReplay {
public:
    // `recording` as loadRecording read it (its first event a state).
    explicit SessionReplay(SessionRecording recording);

    // The state in force: the first event's until advance() applies others.
    const RecordedState& state() const { return state_; }
    // The screenshot to take before the replay goes on, if any.
    const std::optional<RecordedScreenshot>& pendingScreenshot() const { return pending_; }

    // Applies the events of the current frame in order, up to a screenshot (which becomes
    // pending, the frame not yet passed), or else all of them and passes to the next frame.
    // Does nothing while a screenshot is pending. Returns whether the state changed.
    bool advance();
    // The pending screenshot was saved: the replay goes on from the event after it.
    void screenshotTaken() { pending_.reset(); }

    // Every event applied, no screenshot pending, and the recording's frames shown.
    bool finished() const;
    long frame() const { return frame_; }
    long frames() const { return recording_.frames; }

private:
    SessionRecording recording_;
    RecordedState state_;
    std::optional<RecordedScreenshot> pending_;
    std::size_t next_ = 0; // the next event to apply
    long frame_ = 0;       // the recording's frame the replay is at
};

} // namespace raylab::viewer
