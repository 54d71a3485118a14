#pragma once
// The settings the panel shows while the camera or the light is navigated. Every change of the
// numbers the panel shows makes it re-render its pixels (panel_cache.h), which costs a software
// GL driver 2-3 ms of CPU, shared with the tracer; navigation (held keys, a mouse drag, the
// wheel) changes the camera every frame. So, while the panel is not in use, its copy of the
// settings follows the live ones at most once a period; whenever ImGui wants the mouse or the
// keyboard (the pointer is over the panel, a field is being edited) the copy is the live
// settings, so that every edit starts from them.
//
// Times are steady_clock time points, given by the caller (no clock is read here).

#include "core/render_settings.h"

#include <chrono>
#include <optional>

namespace raylab::viewer {

// How often the panel's settings follow navigation at most (seconds): 10 times a second.
inline constexpr double kPanelSettingsSeconds = 0.1;

class PanelSettingsRefresh {
public:
    using Clock = std::chrono::steady_clock;
    using TimePoint = Clock::time_point;

    // periodSeconds > 0.
    explicit PanelSettingsRefresh(double periodSeconds = kPanelSettingsSeconds);

    // The settings for the panel of a frame at `now`: `live` when the panel is in use, on the
    // first call, or when a period has passed since the copy last changed; else the copy.
    const RenderSettings& shown(const RenderSettings& live, bool panelInUse, TimePoint now);

    // When the copy differs from `live`: the time at which shown() will catch up (a frame to
    // ask for, so that the panel ends on the live numbers). nullopt when it holds them.
    std::optional<TimePoint> catchUpAt(const RenderSettings& live) const;

private:
    Clock::duration period_;
    RenderSettings shown_;
    TimePoint copiedAt_{};
    bool copied_ = false;
};

} // namespace raylab::viewer
