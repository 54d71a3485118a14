#pragma once
// The render thread. It owns the picture's Film (core; two for a split job, one per side) and,
// while the job does not change, adds one sample per pixel per pass (to the side with fewer
// samples) until the job's sample cap; then it sleeps on a condition variable (no CPU use). A new
// job that changes the picture cancels the pass in flight (an atomic flag checked between tiles)
// and restarts; a change of display transform or of the split's divider only re-maps the sums; a
// higher cap continues accumulating; a return to the picture replaced last resumes its samples
// (parked_film.h).
//
// After a restart, when the last passes show a full pass would take longer than a UI frame
// budget, the thread first renders a coarse preview (1/k resolution, upscaled by pixel
// replication) so that moving the camera stays fluid; the picture sharpens when the camera stops.
// A preview in flight is not cancelled by a new job (it takes about one budget): it is shown, and
// the newest job starts after it, so a camera that keeps moving still gets a picture per preview.
// For the same reason a new picture's first full pass is not cancelled when the last passes show
// it fits the budget: while the camera moves faster than passes finish, every pass still ends in
// a picture (at most one budget late) instead of being thrown away for the next step.
//
// Threads: renderPass runs settings.threads workers and this thread is one of them.

#include "loaded_scene.h"
#include "run_stats.h"
#include "shown_image.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace raylab::viewer {

struct RenderJob {
    std::shared_ptr<const LoadedScene> scene;
    // width and height: the render resolution; samplesPerPixel: the sample cap. Must pass
    // validate().
    RenderSettings settings;
    bool keepLinear = false; // also publish the linear picture (for PFM/EXR screenshots)
    // A split picture: left of the divider `settings`, right of it `compare` (any other valid
    // settings of the same size), each side converging on its own film; the worker alternates
    // passes between them. divider: the fraction of the width shown from the left side.
    std::optional<RenderSettings> compare{};
    float divider = 0.5f;
    // How a split shows its two sides: wiped at the divider, or their signed difference on a
    // colour scale with `differenceScale` (W/m^2) in full colour (difference_view.h). Like the
    // divider, they only re-map the samples.
    CompareMode compareMode = CompareMode::Wipe;
    float differenceScale = kDefaultDifferenceScale;
};

// True when two jobs give the same accumulated samples: the same scene and sameSamples() settings
// on each side (display, exposure, cap, thread count and divider do not change the samples).
bool samePicture(const RenderJob& a, const RenderJob& b);
// True when every field of the two jobs is equal (keepLinear aside; the compare mode and scale
// only for split jobs).
bool sameJob(const RenderJob& a, const RenderJob& b);
// The settings of side 0 (left, or the whole picture) or 1 (right of a split).
const RenderSettings& sideSettings(const RenderJob& job, int side);

// The UI frame budget under which a full pass needs no preview first: two frames at 60 Hz.
inline constexpr double kPreviewBudgetSeconds = 1.0 / 30.0;

class RenderWorker {
public:
    // previewBudgetSeconds: a restart renders a preview first when a full pass is expected to
    // take longer than this. onPicture, when set, is called on the render thread after each
    // picture is published (outside the worker's lock), so a waiting UI can wake up; it must be
    // thread-safe and quick (e.g. glfwPostEmptyEvent).
    explicit RenderWorker(double previewBudgetSeconds = kPreviewBudgetSeconds,
                          std::function<void()> onPicture = {});
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;
    // Cancels the pass in flight and joins the thread.
    ~RenderWorker();

    // Replaces the job; returns its serial (1, 2, ...). Cancels the pass in flight when the
    // picture changes, unless it is a preview or a first pass that fits the budget (above).
    uint64_t submit(const RenderJob& job);

    // Moves the newest published picture into `out` when it is newer than out.serial (the buffer
    // `out` held is recycled). Returns whether it did.
    bool takeLatest(ShownImage& out);

    // The passes and previews finished or cancelled so far.
    PassTotals totals() const;

private:
    void run();

    const double previewBudgetSeconds_;
    const std::function<void()> onPicture_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    RenderJob job_;                 // guarded by mutex_
    uint64_t jobSerial_ = 0;        // guarded by mutex_
    bool quit_ = false;             // guarded by mutex_
    bool inPreview_ = false;        // guarded by mutex_: a preview pass is running
    bool inShortFirstPass_ = false; // guarded by mutex_: a first pass that fits the budget runs
    ShownImage latest_;             // guarded by mutex_
    PassTotals totals_;             // guarded by mutex_
    std::atomic<bool> cancel_{false};
    std::thread thread_; // last: starts after every member above exists
};

} // namespace raylab::viewer
