#pragma once
// The lab integrator's fast pass: R = rho * (D + N) with the lab's point light (radius 0) and no
// emitting triangle. Camera rays in 8 x 8 pixel blocks (sample 0 at the pixel centres, later
// samples jittered by a per-(pixel, sample) hash), traced as AVX2 packets and, for small scenes,
// through frustum candidates; every answer is shadeLab's bit for bit.

#include "bvh/bvh.h"
#include "integrators/lab_shading.h"
#include "render/film.h"
#include "render/pass_options.h"
#include "render_settings.h"
#include "scene.h"

namespace raylab {

// renderPass (render/renderer.h) for the case above. Writes the film's moments when it has them.
bool labPass(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Film& film,
             RayCounts* counts, const PassOptions& options);

} // namespace raylab
