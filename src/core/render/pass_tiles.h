#pragma once
// What every pass over a film does around its integrator: spreads the image's tiles over
// settings.threads threads (the film's window of it) (cancel and progress as the options say),
// writes each finished tile's display bytes when asked, adds the tiles' ray counts up, and counts
// the sample in the film when every tile is done. The integrator's body only shades a tile's pixels
// into the film.

#include "integrators/lab_shading.h"
#include "render/film.h"
#include "render/parallel_tiles.h"
#include "render/pass_options.h"
#include "render_settings.h"

#include <functional>

namespace raylab {

// body(tile, counts) writes sample film.nextSample() of the tile's pixels into the film and counts
// its rays in `counts` (a per-tile tally). Tiles are in image pixels (settings.width x
// settings.height) and cover the film's window; film.indexOf(x, y) finds a pixel's sums. Returns
// false when cancelled (the film is then not counted, and partly updated).
bool forEachPassTile(const RenderSettings& settings, Film& film, RayCounts* counts,
                     const PassOptions& options,
                     const std::function<void(const TileRect& tile, RayCounts& counts)>& body);

} // namespace raylab
