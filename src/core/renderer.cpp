#include "renderer.h"

#include "bvh_packet.h"
#include "camera.h"
#include "parallel_tiles.h"
#include "sampling.h"

#include <algorithm>

namespace raylab {

bool accumulatePass(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                    uint32_t sampleIndex, std::span<glm::vec3> sums, RayCounts* counts,
                    const PassOptions& options) {
    const int width = settings.width;
    const PrimaryRays rays(settings.camera, width, settings.height);
    std::atomic<uint64_t> primary{0};
    std::atomic<uint64_t> shadow{0};
    const uint32_t sampleSeed = hash32(sampleIndex);

    TileLoopOptions loop;
    loop.threads = settings.threads;
    loop.cancel = options.cancel;
    if (options.progress) {
        loop.progress = [&](std::size_t done, std::size_t total) {
            options.progress(static_cast<double>(done) / static_cast<double>(total));
        };
    }
    const bool complete = forEachTile(width, settings.height, loop, [&](const TileRect& tile) {
        RayCounts tileCounts;
        // Runs of up to 8 pixels along a row, traced as one packet (shadeLab8).
        Ray packet[kPacketSize];
        glm::vec3 radiance[kPacketSize];
        float px[kPacketSize];
        float py[kPacketSize];
        for (int y = tile.y0; y < tile.y1; ++y) {
            // samplePixelOffset's hash with its row and sample parts hoisted out of the pixels.
            const uint32_t rowSeed = hash32(static_cast<uint32_t>(y) ^ sampleSeed);
            for (int x0 = tile.x0; x0 < tile.x1; x0 += kPacketSize) {
                const int count = std::min(kPacketSize, tile.x1 - x0);
                for (int i = 0; i < count; ++i) {
                    const int x = x0 + i;
                    PixelOffset offset{0.5f, 0.5f};
                    if (sampleIndex != 0) {
                        const uint32_t seed = hash32(static_cast<uint32_t>(x) ^ rowSeed);
                        offset = {unitFloat(seed), unitFloat(hash32(seed ^ 0x9e3779b9U))};
                    }
                    px[i] = static_cast<float>(x) + offset.dx;
                    py[i] = static_cast<float>(y) + offset.dy;
                }
                rays.through8(px, py, count, packet);
                shadeLab8(scene, bvh, settings, packet, count, radiance, tileCounts);
                glm::vec3* row = &sums[static_cast<std::size_t>(y) * width + x0];
                for (int i = 0; i < count; ++i) {
                    row[i] += radiance[i];
                }
            }
        }
        primary.fetch_add(tileCounts.primary, std::memory_order_relaxed);
        shadow.fetch_add(tileCounts.shadow, std::memory_order_relaxed);
    });
    if (counts) {
        counts->primary += primary.load();
        counts->shadow += shadow.load();
    }
    return complete;
}

Framebuffer render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   RayCounts* counts, const PassOptions& options) {
    Framebuffer image(settings.width, settings.height);
    const int samples = settings.samplesPerPixel;
    for (int s = 0; s < samples; ++s) {
        PassOptions pass = options;
        if (options.progress) {
            pass.progress = [&](double fraction) { options.progress((s + fraction) / samples); };
        }
        if (!accumulatePass(scene, bvh, settings, static_cast<uint32_t>(s), image.pixels, counts,
                            pass)) {
            break;
        }
    }
    // The same operation the viewer applies to its sums (sum * (1 / n)), so both give equal bytes.
    const float scale = 1.0f / static_cast<float>(samples);
    for (glm::vec3& p : image.pixels) {
        p *= scale;
    }
    return image;
}

} // namespace raylab
