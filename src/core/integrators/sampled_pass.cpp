#include "integrators/sampled_pass.h"

#include "camera.h"
#include "integrators/path_integrator.h"
#include "integrators/term_views.h"
#include "lights/sphere_light.h"
#include "render/pass_tiles.h"
#include "sampling/hash.h"
#include "sampling/warp.h"

#include <atomic>
#include <cassert>
#include <vector>

namespace raylab {

glm::vec3 shadeLabSampled(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                          const Ray& ray, const PixelSampler& sampler, RayCounts& counts) {
    ++counts.primary;
    const Hit hit = closestHit(bvh, ray);
    if (!hit.found()) {
        return glm::vec3(0.0f);
    }
    const SurfacePoint s = surfaceAt(scene, ray, hit);
    const LightSample light =
        sampleSphereLight(settings, s.point, s.facingNormal, sampler.get2D(1));
    glm::vec3 direct = light.direct;
    if (light.needsShadowRay && direct != glm::vec3(0.0f)) {
        ++counts.shadow;
        if (anyHit(bvh, light.shadowRay)) {
            direct = glm::vec3(0.0f);
        }
    }
    const glm::vec3 emitted =
        kPi * emittedRadiance(scene, hit.triangle, ray.direction, settings.emissionScale);
    return emitted + labRadiance(settings, s.rho, direct);
}

namespace {

// A tile's path samples, traced together: their camera rays and samplers, and where each adds.
struct PathTileBatch {
    std::vector<Ray> cameraRays;
    std::vector<PixelSampler> samplers;
    std::vector<std::size_t> kept;
    std::vector<PathSample> samples;
    PathBatch paths;

    // Room for the paths of `tile`, so that the pushes below never reallocate.
    void reserveFor(const TileRect& tile) {
        const std::size_t pixels = static_cast<std::size_t>(tile.x1 - tile.x0) *
                                   static_cast<std::size_t>(tile.y1 - tile.y0);
        cameraRays.reserve(pixels);
        samplers.reserve(pixels);
        kept.reserve(pixels);
    }
};

} // namespace

bool sampledPass(const Scene& scene, const Bvh& bvh, const EmitterTable& emitters,
                 const RenderSettings& settings, Film& film, RayCounts* counts,
                 const PassOptions& options) {
    const int width = settings.width;
    const std::span<glm::vec3> squares = film.squares();
    const std::span<glm::vec4> indirect = film.indirect();
    const PrimaryRays rays(settings.camera, width, settings.height);
    const bool path = settings.integrator == Integrator::Path;
    return forEachPassTile(
        settings, film, counts, options,
        [&](const TileRect& tile, const PassSample& passSample, RayCounts& tileCounts) {
            const uint32_t sampleIndex = passSample.index;
            const Film::Write how = passSample.how;
            const bool first = how == Film::Write::First;
            // What a sample adds to its pixel's sums (kept: film.indexOf), n the path
            // integrator's N and whether it hit.
            const auto add = [&](std::size_t kept, const glm::vec3& value, const glm::vec4& n) {
                if (!indirect.empty()) {
                    indirect[kept] = first ? n : indirect[kept] + n;
                }
                film.write(kept, value, how);
                if (!squares.empty()) {
                    squares[kept] = first ? value * value : squares[kept] + value * value;
                }
            };
            // The path integrator's beauty samples are traced together (tracePaths).
            const bool batched = path && settings.view == View::Beauty;
            PathTileBatch batch;
            if (batched) {
                batch.reserveFor(tile);
            }
            for (int y = tile.y0; y < tile.y1; ++y) {
                for (int x = tile.x0; x < tile.x1; ++x) {
                    // Samples are drawn per pixel of the whole image; sums kept per pixel of the
                    // film's window.
                    const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
                    const std::size_t kept = film.indexOf(x, y);
                    const PixelSampler sampler(settings.sampler, static_cast<uint32_t>(pixel),
                                               sampleIndex);
                    // Pixel positions: the path integrator's from its sampler, the lab's own.
                    glm::vec2 offset;
                    if (path) {
                        offset = sampler.get2D(0);
                    } else {
                        const PixelOffset o = samplePixelOffset(
                            static_cast<uint32_t>(x), static_cast<uint32_t>(y), sampleIndex);
                        offset = glm::vec2(o.dx, o.dy);
                    }
                    const Ray ray = rays.through(static_cast<float>(x) + offset.x,
                                                 static_cast<float>(y) + offset.y);
                    if (batched) {
                        batch.cameraRays.push_back(ray);
                        batch.samplers.push_back(sampler);
                        batch.kept.push_back(kept);
                    } else if (settings.view != View::Beauty) {
                        add(kept,
                            shadeView(scene, bvh, emitters, settings, ray, sampler, tileCounts),
                            glm::vec4(0.0f));
                    } else {
                        add(kept, shadeLabSampled(scene, bvh, settings, ray, sampler, tileCounts),
                            glm::vec4(0.0f));
                    }
                }
            }
            if (batched) {
                batch.samples.resize(batch.cameraRays.size());
                tracePaths(scene, bvh, emitters, settings, batch.cameraRays, batch.samplers,
                           batch.samples, tileCounts, batch.paths);
                for (std::size_t i = 0; i < batch.samples.size(); ++i) {
                    const PathSample& sample = batch.samples[i];
                    add(batch.kept[i], sample.radiance,
                        glm::vec4(sample.indirect, sample.hit ? 1.0f : 0.0f));
                }
            }
        });
}

} // namespace raylab
