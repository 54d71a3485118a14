#include "panel_settings_refresh.h"

namespace raylab::viewer {

PanelSettingsRefresh::PanelSettingsRefresh(double periodSeconds)
    : period_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(periodSeconds))) {}

const RenderSettings& PanelSettingsRefresh::shown(const RenderSettings& live, bool panelInUse,
                                                  TimePoint now) {
    if (!copied_ || panelInUse || now - copiedAt_ >= period_) {
        if (!copied_ || !(shown_ == live)) {
            copiedAt_ = now;
        }
        shown_ = live;
        copied_ = true;
    }
    return shown_;
}

std::optional<PanelSettingsRefresh::TimePoint>
PanelSettingsRefresh::catchUpAt(const RenderSettings& live) const {
    if (copied_ && shown_ == live) {
        return std::nullopt;
    }
    return copied_ ? copiedAt_ + period_ : TimePoint{};
}

} // namespace raylab::viewer
