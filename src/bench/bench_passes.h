#pragma once
// The renderer's own passes on the bench's scene and camera: pixel samples per second of each
// integrator, made as raylab-render and the viewer make them (core's renderPass into a Film), on
// 1 thread and on all threads, best of the frames.

#include "core/bvh/bvh.h"
#include "core/render_settings.h"
#include "core/scene.h"

#include <cstdint>

namespace raylab::bench {

struct PassFigures {
    double oneThread = 0.0;  // M pixel samples per second
    double allThreads = 0.0; // likewise
};

// `settings` gives the camera, light and image size; its integrator is the one measured. Each
// timed pass writes `samplesPerPass` samples of every pixel (PassOptions::samples): 1 as the
// viewer renders, kSamplesPerPass as raylab-render does.
PassFigures measurePasses(const Scene& scene, const Bvh& bvh, RenderSettings settings, int threads,
                          int frames, uint32_t samplesPerPass = 1);

} // namespace raylab::bench
