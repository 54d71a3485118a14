#pragma once
// What every pass over a film does around its integrator: spreads the image's tiles over
// settings.threads threads (the film's window of it) (cancel and progress as the options say),
// writes each finished tile's display bytes when asked, adds the tiles' ray counts up, and counts
// the samples in the film when every tile is done. The integrator's body only shades a tile's
// pixels into the film.

#include "integrators/lab_shading.h"
#include "render/film.h"
#include "render/parallel_tiles.h"
#include "render/pass_options.h"
#include "render_settings.h"

#include <functional>

namespace raylab {

// One sample of a pass: its index (the same for every pixel) and how the film takes it.
struct PassSample {
    uint32_t index = 0;
    Film::Write how = Film::Write::First;
};

// body(tile, sample, counts) writes `sample` of the tile's pixels into the film and counts its
// rays in `counts` (a per-tile tally); it is called for each of the pass's options.samples
// samples of a tile, in order, before the next tile. Tiles are in image pixels (settings.width x
// settings.height) and cover the film's window; film.indexOf(x, y) finds a pixel's sums. Returns
// false when cancelled (the film is then not counted, and partly updated).
bool forEachPassTile(const RenderSettings& settings, Film& film, RayCounts* counts,
                     const PassOptions& options,
                     const std::function<void(const TileRect& tile, const PassSample& sample,
                                              RayCounts& counts)>& body);

} // namespace raylab
