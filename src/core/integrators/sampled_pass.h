#pragma once
// A pass that traces each pixel's sample on its own: the path integrator, the lab integrator
// where its fast pass does not apply (a sphere light, or emitting triangles), and the views of
// one term (term_views.h). Each pixel's numbers
// come from a PixelSampler of (pixel, sample index), so any thread count gives the same bytes.
//
// Pixel positions: the lab integrator keeps its own (sample 0 at the centre, then the per-(pixel,
// sample) hash of sampling/hash.h), so that its pictures match the fast pass's; the path
// integrator draws them from the sampler's pair 0, like every other dimension.

#include "bvh/bvh.h"
#include "integrators/lab_shading.h"
#include "lights/emitters.h"
#include "render/film.h"
#include "render/pass_options.h"
#include "render_settings.h"
#include "sampling/sampler.h"
#include "scene.h"

namespace raylab {

// The lab's model for one camera ray with a sphere light (one sample of it, from the sampler's
// pair 1) and emitting triangles shown as their emitted colour: R = E + rho * (D + N), E = pi * Le
// of a front face seen by the ray. With radius 0 and no emitter it equals shadeLab.
glm::vec3 shadeLabSampled(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                          const Ray& ray, const PixelSampler& sampler, RayCounts& counts);

// renderPass (render/renderer.h) for the cases above, given the scene's emitter table. Writes
// the film's moments and indirect layer when it has them.
bool sampledPass(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                 const RenderSettings& settings, Film& film, RayCounts* counts,
                 const PassOptions& options);

} // namespace raylab
