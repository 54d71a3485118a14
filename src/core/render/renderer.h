#pragma once
// The progressive renderer: each pass adds one sample per pixel to a Film (film.h), made by the
// integrator the settings choose (integrators/). Tiles are spread over threads; every pixel's
// samples are summed in order on one thread, so the bytes never depend on the thread count.

#include "bvh/bvh.h"
#include "integrators/lab_shading.h"
#include "render/film.h"
#include "render/framebuffer.h"
#include "render/pass_options.h"
#include "render_settings.h"
#include "scene.h"

namespace raylab {

// The layers a film needs for these settings: moments and the indirect layer for the path
// integrator (its noise and its mean N); none for the lab's, which stays as fast as it was.
FilmLayers filmLayersFor(const RenderSettings& settings);

// The samples a pass of a whole render takes at most (render(), raylab-render): enough that the
// film's sums of a tile are read from memory once for many samples, few enough that a cancel
// loses little.
inline constexpr int kSamplesPerPass = 16;

// Adds samples film.nextSample() .. film.nextSample() + options.samples - 1 of every pixel of
// the film's window (the whole image of
// settings.width x settings.height, or a crop of it) to the film and counts them. The lab
// integrator's beauty with the lab's point light and no emitter takes the packet and 8 x 8 block
// paths (integrators/lab_pass.h); every other case traces each pixel's sample on its own
// (integrators/sampled_pass.h). When cancelled returns false and restarts the film, whose sums are
// then partly updated and worthless.
bool renderPass(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Film& film,
                RayCounts* counts = nullptr, const PassOptions& options = {});

// A whole render of settings.samplesPerPixel samples, averaged (film.mean()), in passes of up to
// kSamplesPerPass samples. Settings must pass validate(). Cancelled: the samples of the passes
// finished so far, averaged.
Framebuffer render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   RayCounts* counts = nullptr, const PassOptions& options = {});

} // namespace raylab
