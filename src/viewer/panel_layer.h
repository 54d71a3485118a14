#pragma once
// The panel as a layer of the window: it draws the panel (panel.h) into the frame's Dear ImGui
// draw data and composites that draw data over the picture from cached pixels (panel_cache.h),
// which are rendered again only when what ImGui draws changed. On a software GL driver that
// rendering costs 2-4 ms of CPU, shared with the tracer, so the panel shows numbers that change
// with every frame through copies that change at most once a period (throttled_copy.h):
//  - the statistics (PanelNumbers), every kPanelNumbersPeriod;
//  - the settings, while the camera or the light is navigated, every kPanelSettingsPeriod;
//    while the panel is in use (ImGui wants the mouse or the keyboard: the pointer is over it, a
//    field is being edited) they are the live settings, so that every edit starts from them.
// nextWake says when a copy will catch up with the live values, so that the panel ends on them.
//
// Times are steady_clock time points given by the caller: no clock is read here.

#include "panel.h"
#include "panel_cache.h"
#include "panel_numbers.h"
#include "throttled_copy.h"

#include <chrono>
#include <optional>
#include <string>

struct ImDrawData;

namespace raylab::viewer {

// How often the copies the panel shows change at most: the statistics 4 times a second, the
// navigated settings 10 times.
inline constexpr std::chrono::milliseconds kPanelNumbersPeriod{250};
inline constexpr std::chrono::milliseconds kPanelSettingsPeriod{100};

// The settings after a frame of the panel that was offered `offered` (a copy of `live`, maybe
// stale) and left `drawn`: `drawn` when the panel changed them (an edit), else `live`.
const RenderSettings& settingsAfterPanel(const RenderSettings& live, const RenderSettings& offered,
                                         const RenderSettings& drawn);

class PanelLayer {
public:
    using Clock = std::chrono::steady_clock;
    using TimePoint = Clock::time_point;

    // Periods > 0.
    explicit PanelLayer(Clock::duration numbersPeriod = kPanelNumbersPeriod,
                        Clock::duration settingsPeriod = kPanelSettingsPeriod);

    // Makes the cache's GL objects. Needs a current OpenGL 3.3 core context and ImGui's OpenGL3
    // backend for the layer's whole life (from here on). Returns false with a one-line error.
    bool create(std::string& error);

    // Draws the panel into the current ImGui frame (between NewFrame and Render), at `now`, with
    // `view` and the copies of `liveNumbers` and of state.settings. `state` takes what the panel
    // changed (its text fields, messages, options), and its settings only when the panel edited
    // the copy it drew (settingsAfterPanel). panelInUse: ImGui wants the mouse or the keyboard.
    // No GL.
    PanelActions draw(PanelState& state, PanelView view, const PanelNumbers& liveNumbers,
                      bool panelInUse, TimePoint now);

    // Draws `data` (the frame's draw data: the panel's and anything else ImGui drew, such as the
    // key list) over the default framebuffer of framebufferWidth x framebufferHeight pixels
    // (nothing when a side is 0); for every frame, whether or not draw() ran. Needs create().
    // Leaves the default framebuffer bound, blending and scissor off and the viewport at the
    // whole framebuffer.
    void composite(ImDrawData& data, int framebufferWidth, int framebufferHeight);

    // The earliest time at which a copy shown will catch up with the live settings or picture
    // facts (window timings do not count: they change with every frame drawn); nullopt when the
    // panel shows both. A time in the past when nothing was drawn yet.
    std::optional<TimePoint> nextWake(const RenderSettings& liveSettings,
                                      const PanelNumbers& liveNumbers) const;

private:
    ThrottledCopy<PanelNumbers, &PanelNumbers::picture> numbers_;
    ThrottledCopy<RenderSettings> settings_;
    PanelCache cache_;
};

} // namespace raylab::viewer
