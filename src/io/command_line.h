#pragma once
// The options raylab-render, raylab (the viewer) and raylab-bench share, parsed into one struct.
// Flags override --settings FILE.json, which overrides the defaults (the lab's, or for a mesh the
// framing of core/scene_framing.h).

#include "core/cornell_box.h"
#include "core/lab_presets.h"
#include "core/render/film.h"
#include "core/render_settings.h"
#include "core/scene.h"
#include "core/scene_framing.h"
#include "io/import_limits.h"
#include "io/settings_json.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

enum class Program { Render, Viewer, Bench };

// raylab-bench's picture unless --width or --height is given (a settings file's size does not
// count: the bench's figures compare at one size).
inline constexpr int kBenchWidth = 1280;
inline constexpr int kBenchHeight = 720;

// raylab-bench's own options.
struct BenchOptions {
    bool bounceWorkload = false;  // --workload bounce (default primary)
    bool scalar = false;          // --scalar: raylab's scalar reference traversal
    bool noEmbree = false;        // --no-embree
    bool noPackets = false;       // --no-packets: raylab's single rays only
    bool noBlocks = false;        // --no-blocks
    bool noPasses = false;        // --no-passes: no renderer passes
    float spatialBudget = -1.0f;  // --spatial-budget F; < 0: BvhBuildOptions' default
    float presplitBudget = -1.0f; // --presplit-budget F; likewise
    float spatialMinGain = -1.0f; // --spatial-min-gain F; likewise
    std::string embreeIsa;        // --embree-isa NAME; empty: Embree's own choice
};

// The viewer's sample cap (--spp) and picture size (--width x --height) unless a flag or the
// --settings file gives them: progressive anti-aliasing instead of the lab's single sample.
inline constexpr int kViewerSampleCap = 64;
inline constexpr int kViewerWidth = 1024;
inline constexpr int kViewerHeight = 640;
// The range of the viewer's panel scale (--ui-scale, and the monitor's content scale).
inline constexpr float kMinUiScale = 0.5f;
inline constexpr float kMaxUiScale = 4.0f;

// The viewer's own options.
struct ViewerFlags {
    bool showPanel = true;        // --no-panel starts with the panel hidden (F1 shows it)
    std::string readback;         // --readback FILE: test mode (with --frames), see viewer_app.h
    float resolutionScale = 1.0f; // --resolution-scale S in [0.1, 1]: render size = picture * S
    std::string stats;            // --stats FILE: frame rates and pass times at exit (run_stats.h)
    std::string drop;             // --drop FILE: acts as FILE dropped on the window
    std::string record;           // --record FILE.json: the session's changes (session_recording.h)
    std::string replay;           // --replay FILE.json: plays a recorded session back
    // --ui-scale S in [kMinUiScale, kMaxUiScale]: the panel's scale (font and sizes) instead of
    // the monitor's content scale; 0: the monitor's.
    float uiScale = 0.0f;
};

// The instruction sets --embree-isa accepts, as Embree's "isa=" device configuration names them.
// Embree itself reads an unknown name as SSE2, so the bench refuses one instead.
bool isEmbreeIsa(const std::string& isa);

struct CommandLine {
    std::string scene{kLabBoxName};
    RenderSettings settings;
    // Which parts were given (by flag or settings file); a mesh scene frames the rest.
    bool cameraGiven = false; // position, yaw or pitch
    bool lightGiven = false;  // the light's position
    bool shadowEpsilonGiven = false;
    GivenSettings given;             // the same, field by field
    std::optional<glm::vec3> lookAt; // --look-at, applied after the scene is known
    ImportLimits importLimits;       // --import-memory-limit, --import-time-limit

    bool help = false;
    std::string output;                // render: -o FILE
    std::string saveSettings;          // --save-settings FILE.json
    std::string reference;             // render: --reference FILE.pfm|.exr
    float targetError = 0.0f;          // render: --target-error E, 0 = off
    const LabPreset* preset = nullptr; // --preset NAME, the last one given
    bool inspect = false;              // render: --inspect X,Y (then -o is optional)
    int inspectX = 0;
    int inspectY = 0;
    // render: --samples A:B renders samples [firstSample, settings.samplesPerPixel) of each pixel
    // (--spp N is 0:N)
    uint32_t firstSample = 0;
    std::string partial;            // render: --partial FILE.exr, the sums instead of a picture
    std::optional<FilmWindow> crop; // render: --crop X0,Y0,X1,Y1, only these pixels
    // render: the frames of an animation: --turntable N makes them (once the scene is known),
    // --frames-from FILE.json (or --settings) lists them; --frame K renders frame K's camera,
    // --save-frames FILE.json writes the list with the settings
    int turntable = 0;
    std::vector<Camera> frameCameras;
    int frame = -1;
    std::string saveFrames;
    // viewer
    int frames = 0;                  // --frames N: quit after N shown frames (0 = run until closed)
    std::string screenshot;          // --screenshot FILE: save the last shown frame
    std::string screenshotDir = "."; // --screenshot-dir DIR
    float split = -1.0f; // --split D: start with the A/B split, its divider at D in [0, 1]; < 0 off
    CameraBookmarks bookmarks; // the viewer's, from the --settings file
    // The viewer's observer view, from the --settings file's "observer" record: the settings'
    // camera is the observer's, and this the lab camera kept (raylab-render renders the camera).
    std::optional<Camera> observedLabCamera;
    ViewerFlags viewer;
    // bench
    bool json = false;   // --json
    int benchFrames = 5; // --frames N for the bench: best of N
    BenchOptions bench;
};

// Returns 0 on success; 2 with a one-line `error` for usage errors (unknown flag, missing or
// malformed or out-of-range value); 1 when --settings names a file that cannot be read or parsed.
// `error` does not start with the program's name; callers print "<program>: <error>".
// With --help anywhere (before "--"), returns 0 with help set and nothing else parsed.
// When the --settings file has a "scene" and no SCENE is given, that scene is used.
int parseCommandLine(int argc, const char* const* argv, Program program, CommandLine& out,
                     std::string& error);

std::string usage(Program program);

// Once the scene is loaded: core's placeForScene (the lab's camera and light for the lab's box,
// frameScene's for a mesh) except for what the user gave; then --look-at turns the camera; then
// --turntable makes the frames about the scene's centre from that camera, and --frame K takes
// frame K's camera. Returns an empty string, or one line when the result fails validate() (e.g.
// a look-at point straight above the camera) or names a frame that does not exist.
std::string finishSettings(const Scene& scene, CommandLine& commandLine);

} // namespace raylab
