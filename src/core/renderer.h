#pragma once
// The progressive renderer: each pass adds one sample per pixel into a buffer of sums; the image
// is the sums divided by the number of passes. Tiles are spread over threads; every pixel's
// samples are summed in order on one thread, so the bytes never depend on the thread count.

#include "bvh.h"
#include "display_transform.h"
#include "framebuffer.h"
#include "lab_shading.h"
#include "render_settings.h"
#include "scene.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <span>

namespace raylab {

struct PassOptions {
    const std::atomic<bool>* cancel = nullptr; // checked between tiles
    // Called on the calling thread with the fraction of the pass done, in [0, 1].
    std::function<void(double fraction)> progress;
    // When not empty (4 * width * height bytes): as soon as the pass has added its samples to a
    // tile, the tile's pixels are written here, on the tile's thread, exactly as
    // toRgba8(sums, 1 / (sampleIndex + 1), settings.display, settings.exposure, displayOrder)
    // writes them.
    std::span<uint8_t> displayRgba;
    PixelOrder displayOrder = PixelOrder::Rgba;
};

// Sample `sampleIndex` (0 = the pixel centre) of every pixel into sums (width * height,
// row-major from the top): sample 0 is stored (whatever sums held before, so a new picture needs
// no clearing), a later sample is added to sums, which must then hold samples 0 to
// sampleIndex - 1. Returns false, leaving sums partly updated, when cancelled.
bool accumulatePass(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                    uint32_t sampleIndex, std::span<glm::vec3> sums, RayCounts* counts = nullptr,
                    const PassOptions& options = {});

// A whole render of settings.samplesPerPixel samples, averaged. Settings must pass validate().
Framebuffer render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   RayCounts* counts = nullptr, const PassOptions& options = {});

} // namespace raylab
