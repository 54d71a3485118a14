#include "viewer_options.h"

#include "view_layout.h"

#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace raylab::viewer {

namespace {

// True when argv has `flag` as an option (alone or as --flag=value).
bool hasFlag(const std::vector<const char*>& args, std::string_view flag) {
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string_view arg = args[i];
        if (arg == flag || (arg.size() > flag.size() && arg.substr(0, flag.size()) == flag &&
                            arg[flag.size()] == '=')) {
            return true;
        }
    }
    return false;
}

// The value after the flag at argv[i], a finite number in [least, most], into `value`; i moves
// past it. False when it is missing or not such a number.
bool scaleValue(int argc, const char* const* argv, int& i, float least, float most, float& value) {
    if (i + 1 >= argc) {
        return false;
    }
    const char* text = argv[++i];
    char* end = nullptr;
    const float read = std::strtof(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(read) || !(read >= least) ||
        !(read <= most)) {
        return false;
    }
    value = read;
    return true;
}

} // namespace

int parseViewerOptions(int argc, const char* const* argv, ViewerOptions& options,
                       std::string& error) {
    // Take the viewer's own flags out; pass the rest to the shared parser.
    std::vector<const char*> shared;
    for (int i = 0; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (i > 0 && arg == "--no-panel") {
            options.showPanel = false;
        } else if (i > 0 && arg == "--readback") {
            if (i + 1 >= argc) {
                error = "--readback needs a file name";
                return 2;
            }
            options.readback = argv[++i];
        } else if (i > 0 && arg == "--drop") {
            if (i + 1 >= argc) {
                error = "--drop needs a file name";
                return 2;
            }
            options.drop = argv[++i];
        } else if (i > 0 && arg == "--stats") {
            if (i + 1 >= argc) {
                error = "--stats needs a file name";
                return 2;
            }
            options.stats = argv[++i];
        } else if (i > 0 && arg == "--ui-scale") {
            if (!scaleValue(argc, argv, i, kMinUiScale, kMaxUiScale, options.uiScale)) {
                error = "--ui-scale needs a number in [0.5, 4]";
                return 2;
            }
        } else if (i > 0 && arg == "--resolution-scale") {
            if (!scaleValue(argc, argv, i, 0.1f, 1.0f, options.resolutionScale)) {
                error = "--resolution-scale needs a number in [0.1, 1]";
                return 2;
            }
        } else {
            shared.push_back(argv[i]);
        }
    }
    const int status = parseCommandLine(static_cast<int>(shared.size()), shared.data(),
                                        Program::Viewer, options.command, error);
    if (status != 0) {
        return status;
    }
    const bool fromFile = hasFlag(shared, "--settings");
    RenderSettings& settings = options.command.settings;
    if (!fromFile && !hasFlag(shared, "--spp")) {
        settings.samplesPerPixel = kDefaultSampleCap;
    }
    if (!fromFile && !hasFlag(shared, "--width") && !hasFlag(shared, "--height")) {
        settings.width = kDefaultWindowWidth;
        settings.height = kDefaultWindowHeight;
    }
    if (!options.readback.empty() && options.command.frames <= 0) {
        error = "--readback needs --frames N";
        return 2;
    }
    return 0;
}

std::string viewerUsage() {
    return usage(Program::Viewer) +
           "\nViewer only:\n"
           "  --no-panel         start with the panel hidden (F1 toggles it)\n"
           "  --resolution-scale S  render at the picture's size times S, 0.1..1 (default 1)\n"
           "  --ui-scale S       the panel's scale (font and sizes), 0.5..4, instead of the\n"
           "                     monitor's content scale\n"
           "  --readback FILE    test mode: with --frames, also save what the window shows (read\n"
           "                     back from the GL framebuffer) of the last frame as PNG\n"
           "  --stats FILE       on quitting, write the window's frame rate, the tracer's pass\n"
           "                     times and the panel's last readouts (JSON) to FILE\n"
           "  --drop FILE        once the window shows, act as if FILE were dropped on it (a mesh\n"
           "                     opens; a raylab screenshot's .png or .json restores it)\n"
           "The sample cap is --spp (default " +
           std::to_string(kDefaultSampleCap) +
           "). With --frames N and --screenshot or --readback, the viewer shows at least N frames\n"
           "and keeps going until the picture has reached the sample cap, then saves and quits.\n"
           "Keys: Up/Down move, Left/Right turn, W/S A/D Q/E move the light, mouse drag turns,\n"
           "wheel moves, F12 screenshot, F1 panel, Escape quits (or cancels a scene load); H in\n"
           "the window lists every key.\n"
           "A key press moves one step; a key held longer than 0.25 s moves smoothly, 25 steps a\n"
           "second, until released. Dropping a mesh file on the window opens it; dropping a "
           "raylab\n"
           "screenshot (.png or .json) restores its scene and settings.\n";
}

} // namespace raylab::viewer
