#include "integrators/pixel_inspection.h"

#include "camera.h"
#include "integrators/lab_shading.h"
#include "lights/sphere_light.h"
#include "render/display_transform.h"
#include "sampling/warp.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

namespace {

constexpr int kSphereSamples = 256;

} // namespace

PixelInspection inspectPixel(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                             const RenderSettings& settings, int x, int y) {
    PixelInspection out;
    out.x = x;
    out.y = y;
    const PrimaryRays rays(settings.camera, settings.width, settings.height);
    const Ray ray = rays.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    const Hit hit = closestHitCounted(bvh, ray, out.cameraCost);
    if (!hit.found()) {
        return out;
    }
    out.hit = true;
    out.triangle = hit.triangle;
    out.material = scene.triangles[hit.triangle].material;
    out.t = hit.t;
    const SurfacePoint s = surfaceAt(scene, ray, hit);
    out.point = s.point;
    out.rho = s.rho;
    out.normal = s.facingNormal;
    out.toLight = settings.light.position - s.point;
    out.distance = glm::length(out.toLight);
    out.cosTheta =
        out.distance > 0.0f ? glm::dot(out.toLight / out.distance, s.facingNormal) : 0.0f;
    out.shadowEpsilon = settings.shadowEpsilon;
    out.shadowTMax = out.distance - settings.shadowEpsilon;
    out.emitted = kPi * emittedRadiance(scene, hit.triangle, ray.direction, settings.emissionScale);

    // The shadow ray to the light's centre (the lab's), and its closest blocker.
    const LightSample point = lightAt(settings, s.point, s.facingNormal);
    out.directUnshadowed = point.direct; // lightAt's own arithmetic: what R uses, bit for bit
    if (point.needsShadowRay) {
        out.shadowTested = true;
        const Hit blocker = closestHit(bvh, point.shadowRay);
        anyHitCounted(bvh, point.shadowRay, out.shadowCost);
        if (blocker.found()) {
            out.blocker = ShadowBlocker{blocker.triangle, blocker.t};
        }
    }
    RayCounts counts;
    if (settings.light.radius == 0.0f) {
        out.shadowed = out.blocker.has_value();
        out.visibility = out.shadowed ? 0.0f : 1.0f;
        out.direct = out.shadowed ? glm::vec3(0.0f) : point.direct;
    } else {
        glm::vec3 sum(0.0f);
        int lit = 0;
        int facing = 0;
        for (int i = 0; i < kSphereSamples; ++i) {
            const PixelSampler sampler(SamplerKind::Sobol, 0, static_cast<uint32_t>(i));
            const LightSample sample =
                sampleSphereLight(settings, s.point, s.facingNormal, sampler.get2D(0));
            if (sample.direct == glm::vec3(0.0f)) {
                continue;
            }
            ++facing;
            if (!sample.needsShadowRay || !anyHit(bvh, sample.shadowRay)) {
                sum += sample.direct;
                ++lit;
            }
        }
        out.direct = sum / static_cast<float>(kSphereSamples);
        out.visibility = facing > 0 ? static_cast<float>(lit) / static_cast<float>(facing) : 0.0f;
        out.shadowed = facing > 0 && lit == 0;
    }

    if (settings.integrator == Integrator::Lab) {
        out.indirect = settings.indirect3();
        out.radiance = out.emitted + labRadiance(settings, s.rho, out.direct);
    } else {
        const PixelSampler sampler(settings.sampler, static_cast<uint32_t>(y * settings.width + x),
                                   0);
        const PathSample sample = tracePath(scene, bvh, emitters, settings, ray, sampler, counts,
                                            EmitterStrategy::Mis, &out.path);
        out.indirect = sample.indirect;
        out.radiance = sample.radiance;
    }
    const std::array<uint8_t, 3> shown =
        displayPixel(out.radiance, settings.display, settings.exposure);
    std::copy(shown.begin(), shown.end(), out.display.begin());
    return out;
}

} // namespace raylab
