#include "held_keys.h"

#include <algorithm>

namespace raylab::viewer {

namespace {

HeldKeys::Clock::duration seconds(double s) {
    return std::chrono::duration_cast<HeldKeys::Clock::duration>(std::chrono::duration<double>(s));
}

} // namespace

void HeldKeys::press(NavAction action, TimePoint when) {
    release(action, when);
    Key& key = keys_[static_cast<std::size_t>(action)];
    key.held = true;
    key.pressedAt = when;
    key.steps += 1.0;
}

void HeldKeys::release(NavAction action, TimePoint when) {
    Key& key = keys_[static_cast<std::size_t>(action)];
    if (key.held) {
        key.steps += heldSteps(key.pressedAt, when);
        key.held = false;
    }
}

void HeldKeys::releaseAll(TimePoint when) {
    for (std::size_t i = 0; i < kActions; ++i) {
        release(static_cast<NavAction>(i), when);
    }
}

bool HeldKeys::anyHeld() const {
    return std::any_of(keys_.begin(), keys_.end(), [](const Key& key) { return key.held; });
}

std::vector<NavMotion> HeldKeys::advance(TimePoint now) {
    std::vector<NavMotion> motion;
    for (std::size_t i = 0; i < kActions; ++i) {
        Key& key = keys_[i];
        if (key.held) {
            key.steps += heldSteps(key.pressedAt, now);
        }
        if (key.steps > 0.0) {
            motion.push_back({static_cast<NavAction>(i), static_cast<float>(key.steps)});
        }
        key.steps = 0.0;
    }
    lastFrame_ = now;
    return motion;
}

double HeldKeys::heldSteps(TimePoint pressedAt, TimePoint until) const {
    if (!lastFrame_) {
        return 0.0;
    }
    const TimePoint from = std::max(*lastFrame_, pressedAt + seconds(kHoldDelaySeconds));
    const TimePoint to = std::min(until, *lastFrame_ + seconds(kMaxFrameSeconds));
    if (to <= from) {
        return 0.0;
    }
    return kHeldStepsPerSecond * std::chrono::duration<double>(to - from).count();
}

} // namespace raylab::viewer
