#include "key_event_gate.h"

#include <algorithm>

namespace raylab::viewer {

bool KeyEventGate::fitsThisFrame(const KeyboardEvent& event) const {
    if (event.kind == KeyboardEvent::Kind::Char) {
        return !pressedThisFrame_;
    }
    if (event.action != press_ && event.action != release_) {
        return true; // a repeat: no change of state
    }
    const bool modifier =
        std::find(modifiers_.begin(), modifiers_.end(), event.key) != modifiers_.end();
    if (modifier && pressedThisFrame_) {
        return false;
    }
    return std::find(changedKeys_.begin(), changedKeys_.end(), event.key) == changedKeys_.end();
}

void KeyEventGate::count(const KeyboardEvent& event) {
    if (event.kind == KeyboardEvent::Kind::Key &&
        (event.action == press_ || event.action == release_)) {
        changedKeys_.push_back(event.key);
        pressedThisFrame_ = pressedThisFrame_ || event.action == press_;
    }
}

bool KeyEventGate::offer(const KeyboardEvent& event) {
    if (waiting_.empty() && fitsThisFrame(event)) {
        count(event);
        return true;
    }
    waiting_.push_back(event);
    return false;
}

std::vector<KeyboardEvent> KeyEventGate::startFrame() {
    changedKeys_.clear();
    pressedThisFrame_ = false;
    std::vector<KeyboardEvent> now;
    while (!waiting_.empty() && fitsThisFrame(waiting_.front())) {
        count(waiting_.front());
        now.push_back(waiting_.front());
        waiting_.pop_front();
    }
    return now;
}

} // namespace raylab::viewer
