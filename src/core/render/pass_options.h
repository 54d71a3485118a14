#pragma once
// How a caller steers one pass over the film (renderPass, renderer.h).

#include "lights/emitters.h"
#include "render/display_transform.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <span>

namespace raylab {

struct PassOptions {
    // The samples of each pixel the pass writes: nextSample() .. nextSample() + samples - 1 of
    // the film. A tile takes all of them before the next tile, so its pixels' sums stay in the
    // cache: the exact sums are 48 bytes a pixel, and a picture larger than the cache otherwise
    // costs a trip to memory per pixel and sample. The sums are the same bits however the
    // samples are grouped into passes.
    uint32_t samples = 1;
    const std::atomic<bool>* cancel = nullptr; // checked between tiles
    // Called on the calling thread with the fraction of the pass done, in [0, 1].
    std::function<void(double fraction)> progress;
    // When not empty (4 * width * height bytes): as soon as the pass has added its samples to a
    // tile, the tile's pixels are written here, on the tile's thread, exactly as
    // film.toDisplay(..., settings.display, settings.exposure, displayOrder) writes them after the
    // pass.
    std::span<uint8_t> displayRgba;
    PixelOrder displayOrder = PixelOrder::Rgba;
    // buildEmitterTable(scene), kept by a caller that renders many passes of one scene; null:
    // the pass builds it when some material emits.
    const EmitterTable* emitters = nullptr;
};

} // namespace raylab
