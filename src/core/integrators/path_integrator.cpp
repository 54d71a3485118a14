#include "integrators/path_integrator.h"

#include "lights/sphere_light.h"
#include "sampling/warp.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace raylab {

namespace {

// Indirect bounces up to this one are always traced; later ones survive Russian roulette.
constexpr int kBouncesBeforeRoulette = 3;

// The power heuristic's weight of a strategy of density `pdf` against one of density `other`.
float powerHeuristic(float pdf, float other) {
    const float a = pdf * pdf;
    const float b = other * other;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

float maxComponent(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// The weight of next-event estimation's sample (density lightPdf) and of a bounce's hit (density
// bouncePdf) of the same emitter under `strategy`.
float lightWeight(EmitterStrategy strategy, float lightPdf, float bouncePdf) {
    switch (strategy) {
    case EmitterStrategy::Mis: return powerHeuristic(lightPdf, bouncePdf);
    case EmitterStrategy::LightSamplingOnly: return 1.0f;
    case EmitterStrategy::BounceOnly: return 0.0f;
    }
    return 0.0f;
}
float bounceWeight(EmitterStrategy strategy, float bouncePdf, float lightPdf) {
    switch (strategy) {
    case EmitterStrategy::Mis: return powerHeuristic(bouncePdf, lightPdf);
    case EmitterStrategy::LightSamplingOnly: return 0.0f;
    case EmitterStrategy::BounceOnly: return 1.0f;
    }
    return 0.0f;
}

} // namespace

glm::vec3 pathDirectLight(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                          const RenderSettings& settings, const SurfacePoint& s,
                          const PixelSampler& sampler, uint32_t firstPair, EmitterStrategy strategy,
                          RayCounts& counts) {
    glm::vec3 direct(0.0f);
    if (settings.light.intensity > 0.0f) {
        const LightSample light =
            sampleSphereLight(settings, s.point, s.facingNormal, sampler.get2D(firstPair + 2));
        bool lit = light.direct != glm::vec3(0.0f);
        if (lit && light.needsShadowRay) {
            ++counts.shadow;
            lit = !anyHit(bvh, light.shadowRay);
        }
        if (lit) {
            direct += light.direct;
        }
    }
    if (!emitters.empty() && strategy != EmitterStrategy::BounceOnly) {
        const glm::vec2 pick = sampler.get2D(firstPair);
        const EmitterSample e = sampleEmitter(scene, emitters, settings.emissionScale, s.point,
                                              pick.x, sampler.get2D(firstPair + 1));
        const float cosine = glm::dot(e.direction, s.facingNormal);
        if (e.pdf > 0.0f && cosine > 0.0f && e.radiance != glm::vec3(0.0f)) {
            bool visible = true;
            if (settings.shadows) {
                ++counts.shadow;
                visible = !anyHit(bvh, Ray{s.point, e.direction, settings.shadowEpsilon,
                                           e.distance - settings.shadowEpsilon});
            }
            if (visible) {
                const float bouncePdf = cosine / kPi;
                direct += e.radiance * (cosine * lightWeight(strategy, e.pdf, bouncePdf) / e.pdf);
            }
        }
    }
    return direct;
}

namespace {

// What the path integrator needs beyond the path itself.
struct PathContext {
    const Scene& scene;
    const Bvh& bvh;
    const EmitterTable& emitters;
    const RenderSettings& settings;
    EmitterStrategy strategy;
};

// The path at its first surface, where cameraRay found `hit` (counted by the caller).
void startPath(const PathContext& c, const Ray& cameraRay, const Hit& hit,
               const PixelSampler& sampler, RayCounts& counts, PathState& p,
               std::vector<PathVertexRecord>* record) {
    p = PathState{};
    if (!hit.found()) {
        return;
    }
    p.hit = true;
    p.first = surfaceAt(c.scene, cameraRay, hit);
    p.s = p.first;
    // The camera sees an emitter's whole emission: E = pi * Le.
    p.emitted =
        kPi * emittedRadiance(c.scene, hit.triangle, cameraRay.direction, c.settings.emissionScale);
    p.firstDirect = pathDirectLight(c.scene, c.bvh, c.emitters, c.settings, p.first, sampler,
                                    kPathFirstPair, c.strategy, counts);
    p.open = c.settings.indirect && c.settings.maxBounces > 0;
    if (record) {
        record->push_back(
            {p.first.point, p.first.rho, p.firstDirect, p.emitted + p.first.rho * p.firstDirect});
    }
}

// N at the first surface. Its one-sample estimate with a cosine-weighted direction w is R(y) at
// the surface y seen along w: (1/pi) R(y) cos / pdf(w) with pdf = cos / pi. Each later bounce
// estimates its own N the same way, so N is a sum of terms R-at-y weighted by the reflectances
// between (`weight`); emission found by chance gets its MIS weight.
//
// Bounce number `bounce` (1 first) of an open path: its ray, counted, or false when Russian
// roulette ends the path (which then is closed).
bool bounceRay(const PathContext& c, const PixelSampler& sampler, int bounce, PathState& p,
               RayCounts& counts, Ray& ray) {
    const uint32_t pairs = kPathFirstPair + kPathPairsPerVertex * static_cast<uint32_t>(bounce - 1);
    if (bounce > kBouncesBeforeRoulette) {
        // Unbiased Russian roulette: survive with q, and weigh survivors by 1 / q.
        const float q = std::min(1.0f, maxComponent(p.weight));
        if (!(q > 0.0f) || sampler.get2D(pairs).y >= q) {
            p.open = false;
            return false;
        }
        p.weight /= q;
    }
    const glm::vec3 local = cosineHemisphere(sampler.get2D(pairs + 3));
    const glm::vec3 direction = glm::normalize(frameAround(p.s.facingNormal).toWorld(local));
    ray = Ray{p.s.point, direction, c.settings.shadowEpsilon, kInfinity};
    ++counts.bounce;
    return true;
}

// The bounce's ray found `hit`: adds what the surface there gives N, and closes the path on a
// miss or after the last bounce.
void continuePath(const PathContext& c, const PixelSampler& sampler, int bounce, const Ray& ray,
                  const Hit& hit, PathState& p, RayCounts& counts,
                  std::vector<PathVertexRecord>* record) {
    if (!hit.found()) {
        p.open = false;
        return;
    }
    const float cosine = std::max(0.0f, glm::dot(ray.direction, p.s.facingNormal));
    const glm::vec3 le =
        emittedRadiance(c.scene, hit.triangle, ray.direction, c.settings.emissionScale);
    glm::vec3 found(0.0f); // this surface's terms of N at the first surface
    if (le != glm::vec3(0.0f)) {
        const float bouncePdf = cosine / kPi;
        const float lightPdf = emitterPdf(c.scene, c.emitters, hit.triangle, ray.direction, hit.t);
        found += p.weight * (kPi * le * bounceWeight(c.strategy, bouncePdf, lightPdf));
    }
    p.s = surfaceAt(c.scene, ray, hit);
    const uint32_t nextPairs = kPathFirstPair + kPathPairsPerVertex * static_cast<uint32_t>(bounce);
    const glm::vec3 direct = pathDirectLight(c.scene, c.bvh, c.emitters, c.settings, p.s, sampler,
                                             nextPairs, c.strategy, counts);
    found += p.weight * p.s.rho * direct;
    p.indirect += found;
    if (record) {
        record->push_back({p.s.point, p.s.rho, direct, p.first.rho * found});
    }
    p.weight *= p.s.rho;
    p.open = bounce < c.settings.maxBounces;
}

PathSample finishPath(const PathState& p) {
    PathSample result;
    if (p.hit) {
        result.hit = true;
        result.indirect = p.indirect;
        result.radiance = p.emitted + p.first.rho * (p.firstDirect + p.indirect);
    }
    return result;
}

} // namespace

PathSample tracePath(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                     const RenderSettings& settings, const Ray& cameraRay,
                     const PixelSampler& sampler, RayCounts& counts, EmitterStrategy strategy,
                     std::vector<PathVertexRecord>* record) {
    const PathContext c{scene, bvh, emitters, settings, strategy};
    PathState p;
    ++counts.primary;
    startPath(c, cameraRay, closestHit(bvh, cameraRay), sampler, counts, p, record);
    Ray ray;
    for (int bounce = 1; p.open && bounceRay(c, sampler, bounce, p, counts, ray); ++bounce) {
        continuePath(c, sampler, bounce, ray, closestHit(bvh, ray), p, counts, record);
    }
    return finishPath(p);
}

void tracePaths(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                const RenderSettings& settings, std::span<const Ray> cameraRays,
                std::span<const PixelSampler> samplers, std::span<PathSample> samples,
                RayCounts& counts, PathBatch& batch) {
    const PathContext c{scene, bvh, emitters, settings, EmitterStrategy::Mis};
    const std::size_t count = cameraRays.size();
    batch.paths.resize(count);
    batch.hits.resize(count);
    batch.rays.resize(count);
    batch.waiting.resize(count);
    counts.primary += count;
    closestHits(bvh, cameraRays.data(), count, batch.hits.data());
    std::size_t open = 0; // paths waiting for their next bounce: batch.waiting[0, open)
    for (std::size_t i = 0; i < count; ++i) {
        startPath(c, cameraRays[i], batch.hits[i], samplers[i], counts, batch.paths[i], nullptr);
        if (batch.paths[i].open) {
            batch.waiting[open++] = static_cast<uint32_t>(i);
        }
    }
    for (int bounce = 1; open > 0; ++bounce) {
        std::size_t traced = 0; // their rays: batch.rays[0, traced), paths batch.waiting
        for (std::size_t k = 0; k < open; ++k) {
            const uint32_t i = batch.waiting[k];
            if (bounceRay(c, samplers[i], bounce, batch.paths[i], counts, batch.rays[traced])) {
                batch.waiting[traced++] = i;
            }
        }
        closestHits(bvh, batch.rays.data(), traced, batch.hits.data());
        open = 0;
        for (std::size_t k = 0; k < traced; ++k) {
            const uint32_t i = batch.waiting[k];
            continuePath(c, samplers[i], bounce, batch.rays[k], batch.hits[k], batch.paths[i],
                         counts, nullptr);
            if (batch.paths[i].open) {
                batch.waiting[open++] = i;
            }
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        samples[i] = finishPath(batch.paths[i]);
    }
}

} // namespace raylab
