#include "session_state.h"

#include <utility>

namespace raylab::viewer {

RecordedState recordedState(const RenderJob& job, const std::optional<InspectedPixel>& inspected,
                            const std::optional<Camera>& labCamera,
                            const CameraBookmarks& bookmarks) {
    RecordedState state;
    state.scene = job.scene ? job.scene->source : std::string();
    state.settings = job.settings;
    if (job.compare) {
        state.compare = job.compare;
        state.divider = job.divider;
        state.difference = job.compareMode == CompareMode::Difference;
        state.differenceScale = job.differenceScale;
    }
    if (inspected) {
        state.inspected = RecordedInspection{inspected->x, inspected->y, inspected->camera,
                                             inspected->width, inspected->height};
    }
    state.labCamera = labCamera;
    state.bookmarks = bookmarks;
    return state;
}

RenderJob recordedJob(const RecordedState& state, std::shared_ptr<const LoadedScene> scene,
                      const std::optional<RecordedScreenshot>& screenshot) {
    RenderJob job{std::move(scene), state.settings, true};
    if (state.compare) {
        job.compare = state.compare;
        job.divider = state.divider;
        job.compareMode = state.difference ? CompareMode::Difference : CompareMode::Wipe;
        job.differenceScale = state.differenceScale;
    }
    if (screenshot) {
        job.settings.samplesPerPixel = screenshot->samples;
        if (job.compare) {
            job.compare->samplesPerPixel = screenshot->compareSamples;
        }
    }
    return job;
}

bool isScreenshotPicture(const RenderSettings& shown, const std::optional<RenderSettings>& compare,
                         bool preview, const RecordedScreenshot& screenshot) {
    return !preview && shown.samplesPerPixel == screenshot.samples &&
           (compare ? compare->samplesPerPixel == screenshot.compareSamples
                    : screenshot.compareSamples == 0);
}

std::optional<InspectedPixel> inspectedPixel(const RecordedState& state) {
    if (!state.inspected) {
        return std::nullopt;
    }
    const RecordedInspection& i = *state.inspected;
    return InspectedPixel{i.x, i.y, i.camera, i.width, i.height};
}

} // namespace raylab::viewer
