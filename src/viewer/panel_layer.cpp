#include "panel_layer.h"

#include <algorithm>
#include <utility>

namespace raylab::viewer {

const RenderSettings& settingsAfterPanel(const RenderSettings& live, const RenderSettings& offered,
                                         const RenderSettings& drawn) {
    return drawn == offered ? live : drawn;
}

PanelLayer::PanelLayer(Clock::duration numbersPeriod, Clock::duration settingsPeriod)
    : numbers_(numbersPeriod), settings_(settingsPeriod) {}

bool PanelLayer::create(std::string& error) { return cache_.create(error); }

PanelActions PanelLayer::draw(PanelState& state, PanelView view, const PanelNumbers& liveNumbers,
                              bool panelInUse, TimePoint now) {
    numbers_.follow(liveNumbers, now);
    view.numbers = &numbers_.shown();
    settings_.follow(state.settings, now, panelInUse);
    PanelState drawn = state;
    drawn.settings = settings_.shown();
    const PanelActions actions = drawPanel(drawn, view);
    RenderSettings settings = settingsAfterPanel(state.settings, settings_.shown(), drawn.settings);
    state = std::move(drawn);
    state.settings = std::move(settings);
    return actions;
}

void PanelLayer::composite(ImDrawData& data, int framebufferWidth, int framebufferHeight) {
    cache_.draw(data, framebufferWidth, framebufferHeight);
}

std::optional<PanelLayer::TimePoint> PanelLayer::nextWake(const RenderSettings& liveSettings,
                                                          const PanelNumbers& liveNumbers) const {
    const std::optional<TimePoint> numbers = numbers_.catchUpAt(liveNumbers);
    const std::optional<TimePoint> settings = settings_.catchUpAt(liveSettings);
    if (numbers && settings) {
        return std::min(*numbers, *settings);
    }
    return numbers ? numbers : settings;
}

} // namespace raylab::viewer
