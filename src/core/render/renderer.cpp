#include "render/renderer.h"

#include "integrators/lab_pass.h"
#include "integrators/sampled_pass.h"

#include <algorithm>
#include <cassert>

namespace raylab {

FilmLayers filmLayersFor(const RenderSettings& settings) {
    const bool path = settings.integrator == Integrator::Path && settings.view == View::Beauty;
    return FilmLayers{path, path};
}

bool renderPass(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Film& film,
                RayCounts* counts, const PassOptions& options) {
    assert(film.window().x1 <= settings.width && film.window().y1 <= settings.height);
    bool complete = false;
    const bool emitting = hasEmittingMaterial(scene);
    if (settings.integrator == Integrator::Lab && settings.light.radius == 0.0f && !emitting &&
        settings.view == View::Beauty) {
        complete = labPass(scene, bvh, settings, film, counts, options);
    } else {
        EmitterTable built;
        const EmitterTable* emitters = options.emitters;
        if (!emitters) {
            if (emitting) {
                built = buildEmitterTable(scene);
            }
            emitters = &built;
        }
        complete = sampledPass(scene, bvh, *emitters, settings, film, counts, options);
    }
    if (!complete) {
        film.restart();
    }
    return complete;
}

Framebuffer render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   RayCounts* counts, const PassOptions& options) {
    Film film(settings.width, settings.height);
    PassOptions pass = options;
    EmitterTable emitters;
    if (!pass.emitters && hasEmittingMaterial(scene)) {
        emitters = buildEmitterTable(scene);
        pass.emitters = &emitters;
    }
    // Passes of up to kSamplesPerPass samples, each tile taking a pass's samples in turn
    // (PassOptions::samples); a cancel loses at most the pass under way.
    const int samples = settings.samplesPerPixel;
    for (int done = 0; done < samples;) {
        const int now = std::min(kSamplesPerPass, samples - done);
        if (options.progress) {
            pass.progress = [&](double fraction) {
                options.progress((done + fraction * now) / samples);
            };
        }
        pass.samples = static_cast<uint32_t>(now);
        if (!renderPass(scene, bvh, settings, film, counts, pass)) {
            break;
        }
        done += now;
    }
    return film.mean();
}

} // namespace raylab
