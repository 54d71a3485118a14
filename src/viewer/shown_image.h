#pragma once
// One finished picture of the render thread, as the window shows it (the "image block" the UI
// thread reads under a mutex, like Nori's).

#include "core/framebuffer.h"
#include "core/render_settings.h"
#include "io/image_io.h"
#include "loaded_scene.h"

#include <cstdint>
#include <memory>

namespace raylab::viewer {

struct ShownImage {
    Rgba8Image image; // at render resolution, row 0 at the top
    // The linear picture (sums / samples, as raylab-render computes it); only when the job asked
    // for it (RenderJob::keepLinear), and never for a preview.
    Framebuffer linear;
    // What the picture is, exactly: width and height are the image's, samplesPerPixel the samples
    // accumulated so far, display and exposure those applied. For a non-preview image,
    // raylab-render with these settings and the same scene gives the same bytes.
    RenderSettings settings;
    std::shared_ptr<const LoadedScene> scene;
    uint64_t jobSerial = 0;     // RenderWorker::submit's serial of the job this picture shows
    bool preview = false;       // a coarse preview upscaled to render resolution: not reproducible
    bool final = false;         // samples reached the job's cap: nothing more will change
    double passSeconds = 0.0;   // wall clock of the pass that produced it
    double raysPerSecond = 0.0; // primary + shadow rays of that pass per second
    uint64_t serial = 0;        // increases with every picture published
};

} // namespace raylab::viewer
