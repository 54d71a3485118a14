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

PathSample tracePath(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                     const RenderSettings& settings, const Ray& cameraRay,
                     const PixelSampler& sampler, RayCounts& counts, EmitterStrategy strategy,
                     std::vector<PathVertexRecord>* record) {
    PathSample result;
    ++counts.primary;
    Hit hit = closestHit(bvh, cameraRay);
    if (!hit.found()) {
        return result;
    }
    result.hit = true;
    const SurfacePoint first = surfaceAt(scene, cameraRay, hit);
    // The camera sees an emitter's whole emission: E = pi * Le.
    const glm::vec3 emitted =
        kPi * emittedRadiance(scene, hit.triangle, cameraRay.direction, settings.emissionScale);
    const glm::vec3 firstDirect = pathDirectLight(scene, bvh, emitters, settings, first, sampler,
                                                  kPathFirstPair, strategy, counts);
    if (record) {
        record->push_back({first.point, first.rho, firstDirect, emitted + first.rho * firstDirect});
    }

    // N at the first surface. Its one-sample estimate with a cosine-weighted direction w is
    // R(y) at the surface y seen along w: (1/pi) R(y) cos / pdf(w) with pdf = cos / pi. Each later
    // bounce estimates its own N the same way, so N is a sum of terms R-at-y weighted by the
    // reflectances between (`weight`); emission found by chance gets its MIS weight.
    glm::vec3 indirect(0.0f);
    const int bounces = settings.indirect ? settings.maxBounces : 0;
    SurfacePoint s = first;
    glm::vec3 weight(1.0f);
    for (int bounce = 1; bounce <= bounces; ++bounce) {
        const uint32_t pairs =
            kPathFirstPair + kPathPairsPerVertex * static_cast<uint32_t>(bounce - 1);
        if (bounce > kBouncesBeforeRoulette) {
            // Unbiased Russian roulette: survive with q, and weigh survivors by 1 / q.
            const float q = std::min(1.0f, maxComponent(weight));
            if (!(q > 0.0f) || sampler.get2D(pairs).y >= q) {
                break;
            }
            weight /= q;
        }
        const glm::vec3 local = cosineHemisphere(sampler.get2D(pairs + 3));
        const glm::vec3 direction = glm::normalize(frameAround(s.facingNormal).toWorld(local));
        const float cosine = std::max(0.0f, glm::dot(direction, s.facingNormal));
        const Ray ray{s.point, direction, settings.shadowEpsilon, kInfinity};
        ++counts.bounce;
        hit = closestHit(bvh, ray);
        if (!hit.found()) {
            break;
        }
        const glm::vec3 le =
            emittedRadiance(scene, hit.triangle, direction, settings.emissionScale);
        glm::vec3 found(0.0f); // this surface's terms of N at the first surface
        if (le != glm::vec3(0.0f)) {
            const float bouncePdf = cosine / kPi;
            const float lightPdf = emitterPdf(scene, emitters, hit.triangle, direction, hit.t);
            found += weight * (kPi * le * bounceWeight(strategy, bouncePdf, lightPdf));
        }
        s = surfaceAt(scene, ray, hit);
        const uint32_t nextPairs =
            kPathFirstPair + kPathPairsPerVertex * static_cast<uint32_t>(bounce);
        const glm::vec3 direct = pathDirectLight(scene, bvh, emitters, settings, s, sampler,
                                                 nextPairs, strategy, counts);
        found += weight * s.rho * direct;
        indirect += found;
        if (record) {
            record->push_back({s.point, s.rho, direct, first.rho * found});
        }
        weight *= s.rho;
    }
    result.indirect = indirect;
    result.radiance = emitted + first.rho * (firstDirect + indirect);
    return result;
}

} // namespace raylab
