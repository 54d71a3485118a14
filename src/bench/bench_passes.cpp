#include "bench_passes.h"

#include "core/lights/emitters.h"
#include "core/render/film.h"
#include "core/render/renderer.h"

#include <algorithm>
#include <chrono>

namespace raylab::bench {

namespace {

// The best of `frames` passes of `samplesPerPass` samples after a first, untimed pass of one
// sample (sample 0 of the lab integrator is the pixel centres, later ones jittered: the timed
// passes are those of a converging picture).
double bestPassMsamples(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                        const EmitterTable& emitters, int frames, uint32_t samplesPerPass) {
    Film film(settings.width, settings.height, filmLayersFor(settings));
    PassOptions options;
    options.emitters = &emitters;
    renderPass(scene, bvh, settings, film, nullptr, options);
    options.samples = samplesPerPass;
    double best = 1e30;
    for (int i = 0; i < frames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        renderPass(scene, bvh, settings, film, nullptr, options);
        best = std::min(
            best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return static_cast<double>(film.pixelCount()) * samplesPerPass / best * 1e-6;
}

} // namespace

PassFigures measurePasses(const Scene& scene, const Bvh& bvh, RenderSettings settings, int threads,
                          int frames, uint32_t samplesPerPass) {
    const EmitterTable emitters = buildEmitterTable(scene);
    PassFigures figures;
    settings.threads = 1;
    figures.oneThread = bestPassMsamples(scene, bvh, settings, emitters, frames, samplesPerPass);
    settings.threads = threads;
    figures.allThreads = bestPassMsamples(scene, bvh, settings, emitters, frames, samplesPerPass);
    return figures;
}

} // namespace raylab::bench
