#pragma once
// --record FILE.json: the window's session as it happens (io/session_recording.h). The window
// notes its state every time it hands the tracer a job and every screenshot it saves; a state
// equal to the last one noted adds nothing, so a still window records nothing. The recording is
// written whole (atomically) when the window closes.

#include "io/session_recording.h"

#include <optional>
#include <string>

namespace raylab::viewer {

class SessionRecorder {
public:
    // The state shown from frame `frame` on (frames never decrease).
    void note(long frame, const RecordedState& state);
    // A screenshot saved at `frame` of a picture with these samples; after a note().
    void screenshot(long frame, const RecordedScreenshot& shot);
    // Writes what was noted, the session having shown `frames` frames in all. False with a
    // one-line error naming the path, and then no file, when nothing was noted or it cannot be
    // written.
    bool save(const std::string& path, long frames, std::string& error) const;

    const SessionRecording& recording() const { return recording_; }

private:
    SessionRecording recording_;
    std::optional<RecordedState> last_; // the last state noted
};

} // namespace raylab::viewer
