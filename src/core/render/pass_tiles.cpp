#include "render/pass_tiles.h"

#include <atomic>
#include <cassert>

namespace raylab {

bool forEachPassTile(const RenderSettings& settings, Film& film, RayCounts* counts,
                     const PassOptions& options,
                     const std::function<void(const TileRect& tile, const PassSample& sample,
                                              RayCounts& counts)>& body) {
    assert(options.samples >= 1);
    const FilmWindow window = film.window();
    assert(window.x0 >= 0 && window.y0 >= 0 && window.x1 <= settings.width &&
           window.y1 <= settings.height);
    assert(options.displayRgba.empty() || options.displayRgba.size() >= 4 * film.pixelCount());
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
    const bool complete = forEachTile(window.width(), window.height(), loop, [&](TileRect tile) {
        tile.x0 += window.x0;
        tile.x1 += window.x0;
        tile.y0 += window.y0;
        tile.y1 += window.y0;
        RayCounts tileCounts;
        for (uint32_t k = 0; k < options.samples; ++k) {
            body(tile, PassSample{film.nextSample() + k, film.nextWrite(k)}, tileCounts);
        }
        if (!options.displayRgba.empty()) {
            for (int y = tile.y0; y < tile.y1; ++y) {
                const std::size_t first = film.indexOf(tile.x0, y);
                const std::size_t count = static_cast<std::size_t>(tile.x1 - tile.x0);
                film.toDisplayCounting(first, count, options.samples,
                                       options.displayRgba.subspan(4 * first, 4 * count),
                                       settings.display, settings.exposure, options.displayOrder);
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
        film.passFinished(options.samples);
    }
    return complete;
}

} // namespace raylab
