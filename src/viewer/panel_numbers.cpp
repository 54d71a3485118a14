#include "panel_numbers.h"

namespace raylab::viewer {

PanelNumbersRefresh::PanelNumbersRefresh(double periodSeconds)
    : period_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(periodSeconds))) {}

bool PanelNumbersRefresh::update(const PanelNumbers& live, TimePoint now) {
    if (copied_ && now - copiedAt_ < period_) {
        return false;
    }
    shown_ = live;
    copiedAt_ = now;
    copied_ = true;
    return true;
}

std::optional<PanelNumbersRefresh::TimePoint>
PanelNumbersRefresh::catchUpAt(const PanelNumbers& live) const {
    if (copied_ && live.picture == shown_.picture) {
        return std::nullopt;
    }
    return copied_ ? copiedAt_ + period_ : TimePoint{};
}

} // namespace raylab::viewer
