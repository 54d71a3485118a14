#include "observer_view.h"

#include "observer_geometry.h"

#include <utility>

namespace raylab::viewer {

namespace {

RenderSettings withCamera(RenderSettings settings, const std::optional<Camera>& camera) {
    if (camera) {
        settings.camera = *camera;
    }
    return settings;
}

} // namespace

ObserverView::ObserverView(const RenderSettings& initial, const std::optional<Camera>& observedLab)
    : on_(observedLab.has_value()), kept_(observedLab),
      labHistory_(withCamera(initial, observedLab)) {
    if (on_) {
        observerHistory_.emplace(initial);
    }
}

void ObserverView::toggle(RenderSettings& settings, const Aabb& bounds) {
    if (!on_ && !kept_) {
        kept_ = observerStart(settings.camera, bounds);
    }
    std::swap(settings.camera, *kept_);
    on_ = !on_;
    if (on_ && !observerHistory_) {
        observerHistory_.emplace(settings);
    }
    history().adopt(settings);
}

void ObserverView::observe(const Camera& lab, const Camera& observer, RenderSettings& settings) {
    labHistory_.adopt(withCamera(settings, lab));
    on_ = true;
    kept_ = lab;
    settings.camera = observer;
    if (!observerHistory_) {
        observerHistory_.emplace(settings);
    }
    observerHistory_->adopt(settings);
}

void ObserverView::leave(RenderSettings& settings) {
    if (on_) {
        settings.camera = *kept_;
        on_ = false;
        labHistory_.adopt(settings);
    }
    kept_.reset();
    observerHistory_.reset();
}

std::optional<Camera> ObserverView::keptLabCamera() const { return on_ ? kept_ : std::nullopt; }

SettingsHistory& ObserverView::history() { return on_ ? *observerHistory_ : labHistory_; }

} // namespace raylab::viewer
