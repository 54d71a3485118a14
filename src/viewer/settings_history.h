#pragma once
// Undo and redo of the settings (Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y) in steps a person recognises: a
// change becomes a step once the settings have held still for kSettleSeconds, so a slider drag, a
// held key's walk or a mouse drag is one step, not one per frame. The render size (which follows
// the window) is not part of a step: undo keeps the current size.

#include "core/render_settings.h"

#include <chrono>
#include <cstddef>
#include <vector>

namespace raylab::viewer {

inline constexpr double kSettleSeconds = 0.4;
inline constexpr std::size_t kMaxUndoSteps = 256;

class SettingsHistory {
public:
    using Clock = std::chrono::steady_clock;

    explicit SettingsHistory(const RenderSettings& initial);

    // The settings of this frame at `now`: a change that has held still for kSettleSeconds
    // becomes a new step (and forgets the steps undone before it).
    void observe(const RenderSettings& settings, Clock::time_point now);

    // The settings become the current step at once (a new step when they differ from it, which
    // forgets the steps undone): for a history that did not see the settings change meanwhile
    // (the observer view's, observer_view.h, while the other camera moved).
    void adopt(const RenderSettings& settings);

    // The settings one step back (or forward), at `current`'s render size; false (settings
    // unchanged) when there is none. A change not yet settled counts as a step of its own: undo
    // first returns to the last settled settings.
    bool undo(RenderSettings& settings);
    bool redo(RenderSettings& settings);

    std::size_t steps() const { return steps_.size(); }
    std::size_t position() const { return position_; } // index of the current step

private:
    static bool sameStep(const RenderSettings& a, const RenderSettings& b);
    void commit(const RenderSettings& settings);

    std::vector<RenderSettings> steps_; // steps_[position_] is the current settled step
    std::size_t position_ = 0;
    RenderSettings pending_;           // the latest settings seen
    Clock::time_point pendingSince_{}; // when they last changed
};

} // namespace raylab::viewer
