#pragma once
// The renderer's own passes on the bench's scene and camera: pixel samples per second of each
// integrator, made as raylab-render and the viewer make them (core's renderPass into a Film), on
// 1 thread and on all threads, best of the frames.

#include "core/bvh/bvh.h"
#include "core/render_settings.h"
#include "core/scene.h"

namespace raylab::bench {

struct PassFigures {
    double oneThread = 0.0;  // M pixel samples per second
    double allThreads = 0.0; // likewise
};

// `settings` gives the camera, light and image size; its integrator is the one measured.
PassFigures measurePasses(const Scene& scene, const Bvh& bvh, RenderSettings settings, int threads,
                          int frames);

} // namespace raylab::bench
