#pragma once
// The one translation between the window's state and a recording's (io/session_recording.h):
// what --record notes, and what --replay hands the tracer and the panel back.

#include "inspected_pixel.h"
#include "io/session_recording.h"
#include "render_worker.h"

#include <optional>

namespace raylab::viewer {

// The state of a window that submitted `job` (its scene's source is the state's scene).
RecordedState recordedState(const RenderJob& job, const std::optional<InspectedPixel>& inspected,
                            const std::optional<Camera>& labCamera,
                            const CameraBookmarks& bookmarks);

// The job of a recorded state on `scene` (whose source is state.scene), keeping linear pictures
// for screenshots. With `screenshot`, each side's sample cap is that screenshot's samples, so
// the picture stops there (a film beyond them starts again: render_worker.h).
RenderJob recordedJob(const RecordedState& state, std::shared_ptr<const LoadedScene> scene,
                      const std::optional<RecordedScreenshot>& screenshot);

// Whether `shown`-like facts (the job's serial matched by the caller) are the screenshot's
// picture: not a preview, with exactly its samples on each side.
bool isScreenshotPicture(const RenderSettings& shown, const std::optional<RenderSettings>& compare,
                         bool preview, const RecordedScreenshot& screenshot);

std::optional<InspectedPixel> inspectedPixel(const RecordedState& state);

} // namespace raylab::viewer
