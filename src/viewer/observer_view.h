#pragma once
// The observer view (O, or the panel): a second camera that sees the scene, the lab camera and
// its rays from outside, while the lab camera stays where it was. The settings' camera is always
// the camera being moved and rendered (navigation keys, drags, orbit, bookmarks and the panel
// move it); the other camera is kept here, bit for bit, and each camera has its own undo history.

#include "core/aabb.h"
#include "core/camera.h"
#include "core/render_settings.h"
#include "settings_history.h"

#include <optional>

namespace raylab::viewer {

class ObserverView {
public:
    // `initial`: the settings shown at first. With `observedLab` (a settings file of the observer
    // view, SettingsFileExtras::observedLabCamera) the view starts on, initial's camera being the
    // observer's and `observedLab` the lab camera kept.
    explicit ObserverView(const RenderSettings& initial,
                          const std::optional<Camera>& observedLab = std::nullopt);

    bool on() const { return on_; }

    // Switches cameras: settings.camera becomes the kept one and the kept one settings.camera.
    // The first switch to the observer places it with observerStart(lab camera, bounds). The
    // history of the camera now moved takes the settings as its current step
    // (SettingsHistory::adopt).
    void toggle(RenderSettings& settings, const Aabb& bounds);

    // Enters the observer view with `observer` as the observer's camera and `lab` kept as the
    // lab's (a restored screenshot of the observer view); settings.camera becomes `observer`.
    void observe(const Camera& lab, const Camera& observer, RenderSettings& settings);

    // Back to the lab camera, and the observer forgotten (placed anew at the next switch): for a
    // new scene, whose framing then moves the lab camera.
    void leave(RenderSettings& settings);

    // The lab camera, kept while the observer view is on; none while it is off (then it is the
    // settings' camera).
    std::optional<Camera> keptLabCamera() const;

    // The undo history of the camera being moved.
    SettingsHistory& history();

private:
    bool on_ = false;
    // The camera not being moved: the lab's while on, the observer's while off (none before the
    // first switch).
    std::optional<Camera> kept_;
    SettingsHistory labHistory_;
    std::optional<SettingsHistory> observerHistory_; // made at the first switch
};

} // namespace raylab::viewer
