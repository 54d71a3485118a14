#pragma once
// The live numbers the panel's statistics show, and how often the panel shows new ones. A frame
// whose panel looks the same as the previous one reuses the panel's cached pixels (panel_cache.h);
// numbers that change with every frame or picture would defeat that, so the panel shows a copy
// of the numbers refreshed at most every `period` seconds (0.25 s), while the histories behind
// it record every value. Times are steady_clock time points given by the caller.

#include "history.h"

#include <chrono>
#include <glm/vec3.hpp>
#include <optional>

namespace raylab::viewer {

inline constexpr double kPanelNumbersSeconds = 0.25; // the panel's statistics refresh period
inline constexpr std::size_t kHistoryLength = 120;   // values kept per plotted history

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
};

class PanelNumbersRefresh {
public:
    using Clock = std::chrono::steady_clock;
    using TimePoint = Clock::time_point;

    // periodSeconds > 0.
    explicit PanelNumbersRefresh(double periodSeconds = kPanelNumbersSeconds);

    // Copies `live` into shown() when the first call or when at least one period has passed since
    // the last copy. Returns whether it copied.
    bool update(const PanelNumbers& live, TimePoint now);
    // The numbers the panel shows (all zero and empty before the first update).
    const PanelNumbers& shown() const { return shown_; }

    // When the picture's facts shown differ from `live`'s: the time at which update() will copy
    // them (a frame to ask for, so that the last picture's numbers show even when nothing else
    // is drawn). nullopt when they are the same. Window timings do not count here: they change
    // with every frame drawn, and asking for a frame for them would draw frames forever.
    std::optional<TimePoint> catchUpAt(const PanelNumbers& live) const;

private:
    Clock::duration period_;
    PanelNumbers shown_;
    TimePoint copiedAt_{};
    bool copied_ = false;
};

} // namespace raylab::viewer
