#include "settings_history.h"

namespace raylab::viewer {

SettingsHistory::SettingsHistory(const RenderSettings& initial)
    : steps_{initial}, pending_(initial) {}

bool SettingsHistory::sameStep(const RenderSettings& a, const RenderSettings& b) {
    RenderSettings x = a;
    x.width = b.width;
    x.height = b.height;
    return x == b;
}

void SettingsHistory::commit(const RenderSettings& settings) {
    steps_.resize(position_ + 1); // forget the steps undone
    steps_.push_back(settings);
    if (steps_.size() > kMaxUndoSteps) {
        steps_.erase(steps_.begin());
    }
    position_ = steps_.size() - 1;
}

void SettingsHistory::observe(const RenderSettings& settings, Clock::time_point now) {
    if (!sameStep(settings, pending_)) {
        pending_ = settings;
        pendingSince_ = now;
        return;
    }
    if (!sameStep(pending_, steps_[position_]) &&
        std::chrono::duration<double>(now - pendingSince_).count() >= kSettleSeconds) {
        commit(pending_);
    }
}

void SettingsHistory::adopt(const RenderSettings& settings) {
    if (!sameStep(settings, steps_[position_])) {
        commit(settings);
    }
    pending_ = settings;
}

bool SettingsHistory::undo(RenderSettings& settings) {
    if (!sameStep(settings, steps_[position_])) {
        commit(settings); // the unsettled change, so that redo can bring it back
    }
    if (position_ == 0) {
        return false;
    }
    --position_;
    RenderSettings back = steps_[position_];
    back.width = settings.width;
    back.height = settings.height;
    settings = back;
    pending_ = back;
    return true;
}

bool SettingsHistory::redo(RenderSettings& settings) {
    if (position_ + 1 >= steps_.size()) {
        return false;
    }
    ++position_;
    RenderSettings forward = steps_[position_];
    forward.width = settings.width;
    forward.height = settings.height;
    settings = forward;
    pending_ = forward;
    return true;
}

} // namespace raylab::viewer
