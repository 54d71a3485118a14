#include "render/pass_tiles.h"

#include <atomic>
#include <cassert>

namespace raylab {

bool forEachPassTile(const RenderSettings& settings, Film& film, RayCounts* counts,
                     const PassOptions& options,
                     const std::function<void(const TileRect& tile, RayCounts& counts)>& body) {
    const int width = settings.width;
    assert(film.width() == width && film.height() == settings.height);
    assert(options.displayRgba.empty() ||
           options.displayRgba.size() >= 4 * static_cast<std::size_t>(width) * settings.height);
    // Film::scale() once this sample is counted: sum * (1 / n).
    const float displayScale = 1.0f / static_cast<float>(film.samples() + 1);
    const std::span<const glm::vec3> sums = film.sums();
    std::atomic<uint64_t> primary{0};
    std::atomic<uint64_t> shadow{0};
    std::atomic<uint64_t> bounce{0};

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
        body(tile, tileCounts);
        if (!options.displayRgba.empty()) {
            for (int y = tile.y0; y < tile.y1; ++y) {
                const std::size_t first = static_cast<std::size_t>(y) * width + tile.x0;
                const std::size_t count = static_cast<std::size_t>(tile.x1 - tile.x0);
                toRgba8(sums.subspan(first, count), displayScale, settings.display,
                        settings.exposure, options.displayRgba.subspan(4 * first, 4 * count),
                        options.displayOrder);
            }
        }
        primary.fetch_add(tileCounts.primary, std::memory_order_relaxed);
        shadow.fetch_add(tileCounts.shadow, std::memory_order_relaxed);
        bounce.fetch_add(tileCounts.bounce, std::memory_order_relaxed);
    });
    if (counts) {
        counts->primary += primary.load();
        counts->shadow += shadow.load();
        counts->bounce += bounce.load();
    }
    if (complete) {
        film.passFinished();
    }
    return complete;
}

} // namespace raylab
