#pragma once
// What a viewer run measured, written by --stats FILE as one JSON object when the viewer quits:
// frame rates of the window and pass times of the tracer, without any timed test.

#include "pixel_readout.h"

#include <cstdint>
#include <optional>
#include <string>

namespace raylab::viewer {

// count, sum, min and max of a series of measurements (seconds unless named otherwise).
struct Tally {
    uint64_t count = 0;
    double sum = 0.0;
    double min = 0.0; // 0 while count is 0
    double max = 0.0;

    void add(double value);
    double mean() const { return count == 0 ? 0.0 : sum / static_cast<double>(count); }
};

// The render thread's work so far.
struct PassTotals {
    Tally passes;           // full-resolution passes that finished (of pass_size.h's samples)
    Tally previews;         // coarse previews that finished
    uint64_t cancelled = 0; // passes or previews cancelled by a new job
};

struct RunStats {
    bool continuous = false;       // every frame slot drawn (scripted runs); else only when wanted
    uint64_t framesShown = 0;      // frames drawn (buffer swaps)
    double shownSeconds = 0.0;     // from the first swap to the last, minimised time excluded
    double minimisedSeconds = 0.0; // wall clock spent minimised (nothing drawn)
    // Per frame after the first: from when the frame was wanted (a new picture, an event, or,
    // drawing continuously, the previous swap) to its swap (redraw_schedule.h).
    Tally frameResponses;
    uint64_t slowFrames = 0; // frame responses longer than 1/30 s
    Tally drawTimes;         // the UI thread's time per frame, from its start to after the swap
    Tally uploads;           // texture uploads, one per new picture shown (CPU side)
    // New pictures shown of another view than the picture before (render_worker.h's
    // samePicture: camera, light, shadows, indirect light, scene or size changed; a preview
    // counts at full size): while the camera moves, how many of its positions the window showed.
    uint64_t viewsShown = 0;
    PassTotals tracer;
    // The last picture shown: its render resolution and samples per pixel (0 for a preview).
    int width = 0;
    int height = 0;
    int samples = 0;
    std::string scene;
    uint64_t triangles = 0;
    // The panel's readouts at the end: the last pixel read under the cursor, and the mean of the
    // last rectangle dragged (Shift + left drag), when there were any.
    std::optional<PixelReadout> hover;
    std::optional<RectangleMean> rectangle;
};

// The JSON text --stats writes: redraw ("on demand" or "continuous"), frames_shown, seconds,
// window_fps (frames drawn per second), pictures_shown (new pictures of the tracer drawn),
// pictures_per_second, views_shown, views_per_second, frame_ms {mean, max} (frame responses),
// frames_over_33ms, draw_ms {mean, max}, minimised_seconds, upload_ms {count, mean, max}, passes,
// pass_ms {mean, min, max}, previews, preview_ms {mean, min, max}, cancelled_passes, samples,
// render_width, render_height, scene, triangles; when known, hover {pixel [x, y], linear [r, g, b],
// display [r, g, b]} and rectangle {from [x0, y0], to [x1, y1], pixels, mean [r, g, b]}. Times in
// milliseconds unless named seconds.
std::string runStatsJson(const RunStats& stats);

// Writes runStatsJson to `path` atomically; false with a one-line error.
bool writeRunStats(const std::string& path, const RunStats& stats, std::string& error);

} // namespace raylab::viewer
