#pragma once
// One finished picture of the render thread, as the window shows it (the "image block" the UI
// thread reads under a mutex, like Nori's).

#include "core/render/film.h"
#include "core/render/framebuffer.h"
#include "core/render_settings.h"
#include "difference_view.h"
#include "io/image_io.h"
#include "loaded_scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

namespace raylab::viewer {

struct ShownImage {
    // At render resolution, row 0 at the top, bytes B, G, R, A (PixelOrder::Bgra: the order the
    // window's texture keeps, so uploading it is a copy). rgbaOf() gives it as RGBA.
    Rgba8Image bgra;
    // The linear picture (sums / samples, as raylab-render computes it; a difference: see
    // compareMode); only when the job asked for it (RenderJob::keepLinear), and never for a
    // preview.
    Framebuffer linear;
    // What the picture is, exactly: width and height are the image's, samplesPerPixel the samples
    // accumulated so far, display and exposure those applied. For a non-preview image,
    // raylab-render with these settings and the same scene gives the same bytes.
    RenderSettings settings;
    // A split picture: the right side's settings (samplesPerPixel: its samples so far) and the
    // divider, the fraction of the width shown from `settings`. Empty for a whole picture.
    std::optional<RenderSettings> compare;
    float divider = 0.5f;
    // A split shown as the difference (difference_view.h): bgra is the colour scale of
    // settings' side - compare's side at differenceScale, and linear (when kept) the signed
    // difference per channel.
    CompareMode compareMode = CompareMode::Wipe;
    float differenceScale = kDefaultDifferenceScale;
    std::shared_ptr<const LoadedScene> scene;
    uint64_t jobSerial = 0;     // RenderWorker::submit's serial of the job this picture shows
    bool preview = false;       // a coarse preview upscaled to render resolution: not reproducible
    bool final = false;         // samples reached the job's cap: nothing more will change
    double passSeconds = 0.0;   // wall clock of the pass that produced it
    double raysPerSecond = 0.0; // every ray of that pass (camera, shadow, bounce) per second
    NoiseEstimate noise;        // the film's remaining noise (path integrator), Film::noise()
    glm::vec3 meanIndirect{0.0f}; // the path integrator's mean N, Film::meanIndirect()
    uint64_t serial = 0;          // increases with every picture published
};

// The picture with its bytes in RGBA order (for image files).
inline Rgba8Image rgbaOf(const ShownImage& shown) {
    Rgba8Image rgba = shown.bgra;
    for (std::size_t i = 0; i + 3 < rgba.pixels.size(); i += 4) {
        std::swap(rgba.pixels[i], rgba.pixels[i + 2]);
    }
    return rgba;
}

} // namespace raylab::viewer
