#pragma once
// The pixel looked inside (Ctrl+click), pinned in the world: the camera and picture size it was
// picked with are kept, so its rays stay where they were while the camera moves (the overlay
// draws them with the current camera, ray_overlay_geometry.h) and its numbers follow every other
// setting (light, epsilon, N, ...).

#include "core/camera.h"
#include "core/render_settings.h"

namespace raylab::viewer {

struct InspectedPixel {
    int x = 0, y = 0;          // in pixels of the picture it was picked in, y down
    Camera camera;             // the camera that picture was seen with
    int width = 0, height = 0; // that picture's size
    bool operator==(const InspectedPixel&) const = default;
};

// The settings the inspection is computed with: `current` with the pinned camera and size.
inline RenderSettings inspectionSettings(const RenderSettings& current,
                                         const InspectedPixel& pixel) {
    RenderSettings settings = current;
    settings.camera = pixel.camera;
    settings.width = pixel.width;
    settings.height = pixel.height;
    return settings;
}

// Whether the picture of `current` is the one the pixel was picked in (then its marker shows).
inline bool seenAsPicked(const RenderSettings& current, const InspectedPixel& pixel) {
    return current.camera == pixel.camera && current.width == pixel.width &&
           current.height == pixel.height;
}

} // namespace raylab::viewer
