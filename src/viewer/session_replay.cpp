#include "session_replay.h"

#include <utility>

namespace raylab::viewer {

SessionReplay::SessionReplay(SessionRecording recording) : recording_(std::move(recording)) {
    if (!recording_.events.empty() && recording_.events.front().state) {
        state_ = *recording_.events.front().state;
    }
}

bool SessionReplay::advance() {
    if (pending_) {
        return false;
    }
    bool changed = false;
    while (next_ < recording_.events.size() && recording_.events[next_].frame <= frame_) {
        const RecordedEvent& event = recording_.events[next_++];
        if (event.screenshot) {
            pending_ = event.screenshot;
            return changed;
        }
        if (event.state && !(*event.state == state_)) {
            state_ = *event.state;
            changed = true;
        }
    }
    ++frame_;
    return changed;
}

bool SessionReplay::finished() const {
    return next_ == recording_.events.size() && !pending_ && frame_ >= recording_.frames;
}

} // namespace raylab::viewer
