#pragma once
// The path integrator, in the lab's units (DESIGN.md section 5): at each surface point x
//   R(x) = E(x) + rho(x) * (D(x) + N(x)),   N(x) = (1/pi) * integral of R(y) cos(theta) dw,
// E the emitted R (pi * Le, front faces only), D the direct light from the lab's light (point or
// sphere, with the lab's shadow test and eps) and from emitting triangles, y the first surface
// seen in direction w over the hemisphere facing the incoming ray (0 where the ray leaves the
// scene). Diffuse surfaces only; both faces reflect.
//
// Emitting triangles reach D two ways, combined by multiple importance sampling (the power
// heuristic): sampled directly (next-event estimation, a triangle chosen by power) and hit by
// chance by the cosine-weighted bounce. The lab's light is only sampled (it is not geometry).
// With the lab's shadows switched off, shadow rays are not traced: next-event estimation then
// sees emitters through blockers while bounces still stop at the first surface, so that switch
// is a lab experiment, not a light transport to compare with a reference.

#include "bvh/bvh.h"
#include "integrators/lab_shading.h"
#include "lights/emitters.h"
#include "render_settings.h"
#include "sampling/sampler.h"
#include "scene.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace raylab {

// What one path adds to its pixel.
struct PathSample {
    glm::vec3 radiance{0.0f}; // R along the camera ray
    glm::vec3 indirect{0.0f}; // the estimate of N at the first surface (0 on a miss)
    bool hit = false;         // the camera ray hit a surface
};

// The sampler's dimension pairs: pair 0 is the pixel position (the caller's); vertex k of a path
// (0 = where the camera ray lands) uses pairs kPathFirstPair + kPathPairsPerVertex * k + j.
inline constexpr uint32_t kPathFirstPair = 1;
inline constexpr uint32_t kPathPairsPerVertex = 4;

// One surface of a traced path, as the pixel inspector lists it.
struct PathVertexRecord {
    glm::vec3 point{0.0f};
    glm::vec3 rho{0.0f};
    glm::vec3 direct{0.0f}; // D at the point (this sample's estimate, shadows applied)
    glm::vec3 adds{0.0f};   // what this surface adds to the pixel's R (its E and rho * D, times
                            // the reflectances between it and the camera)
};

// A path between its bounces (tracePaths keeps one per path; its fields are the integrator's).
struct PathState {
    SurfacePoint first;          // where the camera ray landed
    SurfacePoint s;              // the last surface reached
    glm::vec3 emitted{0.0f};     // E at the first surface
    glm::vec3 firstDirect{0.0f}; // D at the first surface
    glm::vec3 indirect{0.0f};    // the estimate of N at the first surface so far
    glm::vec3 weight{1.0f};      // the reflectances between the first surface and s
    bool hit = false;            // the camera ray hit a surface
    bool open = false;           // another bounce may follow
};

// How emitting triangles reach D: both ways weighted by MIS (renders), or one way alone with
// weight 1 (tests check that the three agree, and that MIS has the lowest variance).
enum class EmitterStrategy { Mis, LightSamplingOnly, BounceOnly };

// D at surface s as the path integrator computes it: the lab's light (one sample of the sphere
// when it has a radius, pair firstPair + 2) and, by next-event estimation, the emitting triangles
// (pairs firstPair and firstPair + 1), weighted by `strategy` against the bounce's chance of
// hitting them; shadow rays counted.
glm::vec3 pathDirectLight(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                          const RenderSettings& settings, const SurfacePoint& s,
                          const PixelSampler& sampler, uint32_t firstPair, EmitterStrategy strategy,
                          RayCounts& counts);

// One sample of R along cameraRay. `emitters` is buildEmitterTable(scene) (empty for a scene with
// none). Counts the camera ray as primary, shadow rays as shadow and bounce rays as bounce.
// Deterministic in (sampler, arguments).
PathSample tracePath(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                     const RenderSettings& settings, const Ray& cameraRay,
                     const PixelSampler& sampler, RayCounts& counts,
                     EmitterStrategy strategy = EmitterStrategy::Mis,
                     std::vector<PathVertexRecord>* record = nullptr);

// Room for tracePaths' paths between their bounces. tracePaths only resizes it: a caller may
// keep one for many calls (the renderer keeps one per tile).
struct PathBatch {
    std::vector<PathState> paths;
    std::vector<Hit> hits;
    std::vector<Ray> rays;
    std::vector<uint32_t> waiting; // indices of the paths whose next bounce is due
};

// tracePath for many paths at once (the renderer's: one per pixel of a tile), with the same
// answers and counts bit for bit: samples[i] = tracePath(..., cameraRays[i], samplers[i], ...)
// with EmitterStrategy::Mis. The paths advance a bounce at a time, each bounce's rays traced
// together by closestHits (bvh.h), which interleaves them on large scenes. The three spans have
// one length.
void tracePaths(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                const RenderSettings& settings, std::span<const Ray> cameraRays,
                std::span<const PixelSampler> samplers, std::span<PathSample> samples,
                RayCounts& counts, PathBatch& batch);

} // namespace raylab
