#pragma once
// The viewer's command line: the options every raylab program shares (io/command_line.h) plus a
// few of the viewer's own.
//
// The sample cap: settings.samplesPerPixel. The viewer accumulates samples up to it and stops;
// when neither --spp nor --settings gives it, the viewer uses kDefaultSampleCap instead of the
// lab's single sample (progressive anti-aliasing). The picture is --width x --height (or the
// --settings file's size); without them kDefaultWindowWidth x kDefaultWindowHeight. The window
// opens that size plus the panel's column beside it (view_layout.h) when the panel is shown.

#include "io/command_line.h"

#include <string>

namespace raylab::viewer {

inline constexpr int kDefaultSampleCap = 64;
inline constexpr int kDefaultWindowWidth = 1024;
inline constexpr int kDefaultWindowHeight = 640;

struct ViewerOptions {
    CommandLine command;          // shared options; settings.samplesPerPixel is the sample cap
    bool showPanel = true;        // --no-panel starts with the panel hidden (F1 shows it)
    std::string readback;         // --readback FILE: test mode, see viewer_app.h
    float resolutionScale = 1.0f; // --resolution-scale S in [0.1, 1]: render size = window * S
    std::string stats;            // --stats FILE: frame rates and pass times at exit (run_stats.h)
    std::string drop; // --drop FILE: acts as FILE dropped on the window (scripts, tests)
    // --ui-scale S in [0.5, 4]: the panel's scale (font and sizes) instead of the monitor's
    // content scale; 0: the monitor's.
    float uiScale = 0.0f;
};

// Returns 0 on success; 2 with a one-line error for usage errors; 1 for an unreadable --settings
// file (as parseCommandLine).
int parseViewerOptions(int argc, const char* const* argv, ViewerOptions& options,
                       std::string& error);

// The --help text: the shared options and the viewer's own.
std::string viewerUsage();

} // namespace raylab::viewer
