#pragma once
// The live numbers the panel's statistics show: the histories record every value; the panel
// shows a copy of them refreshed a few times a second (panel_layer.h).

#include "history.h"

#include <glm/vec3.hpp>

namespace raylab::viewer {

inline constexpr std::size_t kHistoryLength = 120; // values kept per plotted history

// What the panel says about the picture on screen.
struct PictureFacts {
    int width = 0; // 0: no picture yet
    int height = 0;
    int samples = 0; // samples per pixel accumulated (0 for a preview)
    bool preview = false;
    bool final = false;            // the sample cap was reached
    double passMs = 0.0;           // wall clock of the pass that produced the picture
    double raysPerSecond = 0.0;    // of that pass
    double samplesPerSecond = 0.0; // pixel samples of that pass per second (0 for a preview)
    double noisePercent = -1.0;    // the film's estimated relative error in %; < 0: unknown
    bool pathTraced = false;       // made by the path integrator (meanIndirect holds its N)
    glm::vec3 meanIndirect{0.0f};  // the image's mean path-traced N per channel
    bool operator==(const PictureFacts&) const = default;
};

struct PanelNumbers {
    History frameMs{kHistoryLength};      // intervals between frames drawn (ms)
    History drawMs{kHistoryLength};       // the UI thread's time to draw a frame (ms)
    History passMs{kHistoryLength};       // render pass times (ms)
    History noisePercent{kHistoryLength}; // the estimated error of each new full picture (%)
    double uploadMs = 0.0;                // the last picture's upload
    PictureFacts picture;
    bool operator==(const PanelNumbers&) const = default;
};

} // namespace raylab::viewer
