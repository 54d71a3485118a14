#include "session_recorder.h"

#include <algorithm>

namespace raylab::viewer {

void SessionRecorder::note(long frame, const RecordedState& state) {
    if (last_ && *last_ == state) {
        return;
    }
    recording_.events.push_back({frame, state, std::nullopt});
    last_ = state;
}

void SessionRecorder::screenshot(long frame, const RecordedScreenshot& shot) {
    if (last_) { // else no picture was asked for, so none was saved
        recording_.events.push_back({frame, std::nullopt, shot});
    }
}

bool SessionRecorder::save(const std::string& path, long frames, std::string& error) const {
    if (recording_.events.empty()) {
        error = path + ": not written: the window showed no picture to record";
        return false;
    }
    SessionRecording whole = recording_;
    whole.frames = std::max(frames, recording_.events.back().frame);
    return saveRecording(path, whole, error);
}

} // namespace raylab::viewer
