// The shared command line: one table of options, each with the programs that take it and a
// handler that parses its value into CommandLine. Parsing is two passes: the words are first split
// into options and values (so unknown options and missing values are found before anything is
// applied), then the --settings file is applied, then every other option in the order given.

#include "io/command_line.h"

#include "core/camera.h"
#include "core/lab_presets.h"
#include "core/scene_framing.h"
#include "io/image_io.h"
#include "io/number_parse.h"
#include "io/settings_json.h"
#include "io/text_util.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <vector>

namespace raylab {
namespace {

enum ProgramMask : unsigned {
    kRender = 1u << 0,
    kViewer = 1u << 1,
    kBench = 1u << 2,
    kAll = kRender | kViewer | kBench,
};

unsigned maskOf(Program program) {
    switch (program) {
    case Program::Render: return kRender;
    case Program::Viewer: return kViewer;
    case Program::Bench: return kBench;
    }
    return 0;
}

// What an option handler needs besides the value: the state of the parse so far.
struct ParseState {
    CommandLine& out;
    Program program;
    std::optional<float> focal; // --focal, turned into a field of view once the height is final
    bool fovFlag = false;
};

// Returns an empty string, or what is wrong with the value (the caller adds the option's name).
using Handler = std::function<std::string(const std::string& value, ParseState& state)>;

struct Option {
    const char* name;     // "--width"
    const char* argument; // "N" for the help text; nullptr for a switch
    unsigned programs;
    const char* help;
    Handler handle;
};

std::string quoted(const std::string& value) { return "'" + value + "'"; }

Handler intIn(int lo, int hi, int CommandLine::*field) {
    return [=](const std::string& value, ParseState& s) -> std::string {
        int v = 0;
        if (!parseInt(value, v) || v < lo || v > hi) {
            return "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                   ", got " + quoted(value);
        }
        s.out.*field = v;
        return {};
    };
}

Handler benchSwitch(bool BenchOptions::*field) {
    return [=](const std::string&, ParseState& s) -> std::string {
        s.out.bench.*field = true;
        return {};
    };
}

// A fraction >= 0, and at most `most` when that is finite.
Handler benchFraction(float BenchOptions::*field,
                      float most = std::numeric_limits<float>::infinity()) {
    return [=](const std::string& value, ParseState& s) -> std::string {
        float v = 0.0f;
        if (!parseFloat(value, v) || !(v >= 0.0f) || v > most) {
            if (!std::isfinite(most)) {
                return "expected a fraction >= 0, got " + quoted(value);
            }
            char top[32];
            std::snprintf(top, sizeof top, "%g", most);
            return std::string("expected a fraction in [0, ") + top + "], got " + quoted(value);
        }
        s.out.bench.*field = v;
        return {};
    };
}

Handler viewerScale(float lo, float hi, float ViewerFlags::*field) {
    return [=](const std::string& value, ParseState& s) -> std::string {
        float v = 0.0f;
        if (!parseFloat(value, v) || !(v >= lo) || !(v <= hi)) {
            char range[64];
            std::snprintf(range, sizeof range, "a number in [%g, %g]", lo, hi);
            return "expected " + std::string(range) + ", got " + quoted(value);
        }
        s.out.viewer.*field = v;
        return {};
    };
}

Handler viewerFile(std::string ViewerFlags::*field) {
    return [=](const std::string& value, ParseState& s) -> std::string {
        if (value.empty()) {
            return "expected a file name";
        }
        s.out.viewer.*field = value;
        return {};
    };
}

Handler settingsIntIn(int lo, int hi, int RenderSettings::*field) {
    return [=](const std::string& value, ParseState& s) -> std::string {
        int v = 0;
        if (!parseInt(value, v) || v < lo || v > hi) {
            return "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi) +
                   ", got " + quoted(value);
        }
        s.out.settings.*field = v;
        return {};
    };
}

// A colour as "P" (white light of that power) or "r,g,b" (colour = rgb / max, intensity = max;
// all zero gives colour 1, intensity 0). Every part must be finite and >= 0.
bool parsePower(const std::string& value, glm::vec3& color, float& intensity) {
    glm::vec3 rgb(0.0f);
    float single = 0.0f;
    if (parseFloat(value, single)) {
        rgb = glm::vec3(single);
    } else if (!parseVec3(value, rgb)) {
        return false;
    }
    if (rgb.x < 0.0f || rgb.y < 0.0f || rgb.z < 0.0f) {
        return false;
    }
    splitColourIntensity(rgb, color, intensity);
    return true;
}

std::string expected(const char* what, const std::string& value) {
    return std::string("expected ") + what + ", got " + quoted(value);
}

const std::vector<Option>& options() {
    static const std::vector<Option> table = {
        {"--width", "N", kAll, "image width in pixels, 1..16384 (default 500)",
         settingsIntIn(1, kMaxImageSide, &RenderSettings::width)},
        {"--height", "N", kAll, "image height in pixels, 1..16384 (default 500)",
         settingsIntIn(1, kMaxImageSide, &RenderSettings::height)},
        {"--camera-pos", "X,Y,Z", kAll, "camera position (default 0,0,-3)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseVec3(v, s.out.settings.camera.position)) {
                 return expected("three finite numbers x,y,z", v);
             }
             s.out.given.cameraPosition = true;
             return {};
         }},
        {"--yaw", "DEG", kAll, "turn about the world's y axis, positive to the left (default 0)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseFloat(v, s.out.settings.camera.yawDegrees)) {
                 return expected("a finite angle in degrees", v);
             }
             s.out.given.cameraYaw = true;
             return {};
         }},
        {"--pitch", "DEG", kAll, "look up (positive) or down, within (-90, 90) (default 0)",
         [](const std::string& v, ParseState& s) -> std::string {
             float deg = 0.0f;
             if (!parseFloat(v, deg) || deg <= -90.0f || deg >= 90.0f) {
                 return expected("an angle in degrees within (-90, 90)", v);
             }
             s.out.settings.camera.pitchDegrees = deg;
             s.out.given.cameraPitch = true;
             return {};
         }},
        {"--look-at", "X,Y,Z", kAll, "turn the camera to look at this point (after framing)",
         [](const std::string& v, ParseState& s) -> std::string {
             glm::vec3 target(0.0f);
             if (!parseVec3(v, target)) {
                 return expected("three finite numbers x,y,z", v);
             }
             s.out.lookAt = target;
             return {};
         }},
        {"--fov", "DEG", kAll, "vertical field of view within (0, 180) (default 53.13, the lab's)",
         [](const std::string& v, ParseState& s) -> std::string {
             float deg = 0.0f;
             if (!parseFloat(v, deg) || deg <= 0.0f || deg >= 180.0f) {
                 return expected("an angle in degrees within (0, 180)", v);
             }
             s.out.settings.camera.verticalFovDegrees = deg;
             s.out.given.cameraFov = true;
             s.fovFlag = true;
             return {};
         }},
        {"--focal", "PX", kAll, "focal length in pixels instead of --fov (the lab's is the height)",
         [](const std::string& v, ParseState& s) -> std::string {
             float px = 0.0f;
             if (!parseFloat(v, px) || px <= 0.0f) {
                 return expected("a focal length in pixels > 0", v);
             }
             s.focal = px;
             s.out.given.cameraFov = true;
             return {};
         }},
        {"--light-pos", "X,Y,Z", kAll, "point light position (default 0,0.5,-0.7)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseVec3(v, s.out.settings.light.position)) {
                 return expected("three finite numbers x,y,z", v);
             }
             s.out.given.lightPosition = true;
             return {};
         }},
        {"--light-power", "P|R,G,B", kAll,
         "light power in watts, white or per channel (default 14)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parsePower(v, s.out.settings.light.color, s.out.settings.light.intensity)) {
                 return expected("a power >= 0 or r,g,b with each >= 0", v);
             }
             s.out.given.lightColor = true;
             s.out.given.lightIntensity = true;
             return {};
         }},
        {"--indirect", "V|R,G,B", kAll,
         "constant indirect light, grey or per channel (default 0.5)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parsePower(v, s.out.settings.indirectColor, s.out.settings.indirectIntensity)) {
                 return expected("a value >= 0 or r,g,b with each >= 0", v);
             }
             return {};
         }},
        {"--shadow-eps", "E", kAll, "shadow ray offset in world units, >= 0 (0 shows acne)",
         [](const std::string& v, ParseState& s) -> std::string {
             float eps = 0.0f;
             if (!parseFloat(v, eps) || eps < 0.0f) {
                 return expected("a finite number >= 0", v);
             }
             s.out.settings.shadowEpsilon = eps;
             s.out.given.shadowEpsilon = true;
             return {};
         }},
        {"--no-shadows", nullptr, kAll, "no shadow rays",
         [](const std::string&, ParseState& s) -> std::string {
             s.out.settings.shadows = false;
             return {};
         }},
        {"--no-indirect", nullptr, kAll,
         "no indirect term (the path integrator: direct light only)",
         [](const std::string&, ParseState& s) -> std::string {
             s.out.settings.indirect = false;
             return {};
         }},
        {"--light-radius", "R", kAll,
         "light radius in world units, >= 0: a sphere of the same power (default 0, a point)",
         [](const std::string& v, ParseState& s) -> std::string {
             float radius = 0.0f;
             if (!parseFloat(v, radius) || radius < 0.0f) {
                 return expected("a finite radius >= 0", v);
             }
             s.out.settings.light.radius = radius;
             return {};
         }},
        {"--integrator", "lab|path", kRender | kViewer,
         "light transport: the lab's constant indirect term, or path tracing (default lab)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseIntegrator(lowerCase(v), s.out.settings.integrator)) {
                 return expected("lab or path", v);
             }
             return {};
         }},
        {"--max-bounces", "N", kRender | kViewer,
         "path integrator: indirect bounces, 0 = direct light only (default 8)",
         settingsIntIn(0, kMaxBounces, &RenderSettings::maxBounces)},
        {"--emission-scale", "S", kRender | kViewer,
         "multiplies the emission of the scene's emitting materials, >= 0 (default 1)",
         [](const std::string& v, ParseState& s) -> std::string {
             float scale = 0.0f;
             if (!parseFloat(v, scale) || scale < 0.0f) {
                 return expected("a finite number >= 0", v);
             }
             s.out.settings.emissionScale = scale;
             return {};
         }},
        {"--preset", "NAME", kRender | kViewer,
         "a step of the lab on its box: lab-1-intersection, lab-2-light, lab-3-diffuse, "
         "lab-4-acne, lab-5-shadows, lab-6-indirect (later flags override it)",
         [](const std::string& v, ParseState& s) -> std::string {
             const LabPreset* preset = findLabPreset(lowerCase(v));
             if (preset == nullptr) {
                 std::string names;
                 for (const LabPreset& p : labPresets()) {
                     names += (names.empty() ? "" : ", ") + std::string(p.name);
                 }
                 return expected(("one of " + names).c_str(), v);
             }
             preset->apply(s.out.settings);
             s.out.preset = preset;
             // Its camera, light and epsilon are chosen values: placing the scene keeps them.
             s.out.given = GivenSettings{true, true, true, true, true, true, true, true};
             return {};
         }},
        {"--view", "NAME", kRender | kViewer,
         "beauty (default), or one term alone: albedo, direct, indirect, visibility, normal, "
         "depth, cost",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseView(lowerCase(v), s.out.settings.view)) {
                 return expected(
                     "beauty, albedo, direct, indirect, visibility, normal, depth or cost", v);
             }
             return {};
         }},
        {"--sampler", "sobol|independent", kRender | kViewer,
         "random numbers of the path integrator and the sphere light (default sobol)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseSamplerKind(lowerCase(v).c_str(), s.out.settings.sampler)) {
                 return expected("sobol or independent", v);
             }
             return {};
         }},
        {"--spp", "N", kAll, "samples per pixel, 1 = the lab's centred ray (default 1)",
         [](const std::string& v, ParseState& s) -> std::string {
             std::string why =
                 settingsIntIn(1, kMaxSamplesPerPixel, &RenderSettings::samplesPerPixel)(v, s);
             if (why.empty()) {
                 s.out.firstSample = 0; // --spp N is --samples 0:N
             }
             return why;
         }},
        {"--threads", "N", kAll, "render threads, 0 = all cores (default 0)",
         settingsIntIn(0, kMaxThreads, &RenderSettings::threads)},
        {"--display", "lab|srgb|false-colour", kAll,
         "display transform for 8-bit output: the lab's clamp, sRGB, or a logarithmic false-colour "
         "scale of 16 stops about 2^exposure (default lab)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseDisplayMode(lowerCase(v), s.out.settings.display)) {
                 return expected("lab, srgb or false-colour", v);
             }
             return {};
         }},
        {"--exposure", "EV", kAll,
         "exposure in stops for --display srgb, the middle of the false-colour scale (default 0)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseFloat(v, s.out.settings.exposure)) {
                 return expected("a finite number of stops", v);
             }
             return {};
         }},
        {"--import-memory-limit", "GIB", kAll,
         "memory the mesh importer may use, in GiB (default: a quarter of RAM, 1..4)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseImportLimit(v, kMaxImportMemoryGiB, s.out.importLimits.memoryGiB)) {
                 return expected("a number of GiB > 0 and <= 1024", v);
             }
             return {};
         }},
        {"--import-time-limit", "S", kAll, "seconds a mesh import may take (default 60)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!parseImportLimit(v, kMaxImportSeconds, s.out.importLimits.seconds)) {
                 return expected("a number of seconds > 0 and <= 86400", v);
             }
             return {};
         }},
        {"--settings", "FILE.json", kAll, "load settings saved with --save-settings (flags win)",
         nullptr}, // applied before the other options
        {"--save-settings", "FILE.json", kRender, "save the settings used, as JSON",
         [](const std::string& v, ParseState& s) -> std::string {
             if (v.empty()) {
                 return "expected a file name";
             }
             s.out.saveSettings = v;
             return {};
         }},
        {"-o", "FILE", kRender,
         "output image: .png (8-bit, display transform), .pfm or .exr (linear)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!isSupportedImagePath(v)) {
                 return unsupportedImageReason(v);
             }
             s.out.output = v;
             return {};
         }},
        {"--reference", "FILE", kRender,
         "a converged .pfm or .exr of the same size: print the relative RMSE at 1, 2, 4, ... spp",
         [](const std::string& v, ParseState& s) -> std::string {
             if (v.empty()) {
                 return "expected a file name";
             }
             s.out.reference = v;
             return {};
         }},
        {"--target-error", "E", kRender,
         "stop before --spp once the estimated relative error is below E, in (0, 1)",
         [](const std::string& v, ParseState& s) -> std::string {
             float e = 0.0f;
             if (!parseFloat(v, e) || !(e > 0.0f && e < 1.0f)) {
                 return expected("a relative error in (0, 1), e.g. 0.01", v);
             }
             s.out.targetError = e;
             return {};
         }},
        {"--samples", "A:B", kRender,
         "render samples A (inclusive) to B (exclusive) of every pixel, the samples a full "
         "render draws (--spp N is 0:N)",
         [](const std::string& v, ParseState& s) -> std::string {
             const std::size_t colon = v.find(':');
             int a = -1;
             int b = -1;
             if (colon == std::string::npos || !parseInt(v.substr(0, colon), a) ||
                 !parseInt(v.substr(colon + 1), b) || a < 0 || b <= a || b > kMaxSamplesPerPixel) {
                 return expected(("a range A:B of sample indices, 0 <= A < B <= " +
                                  std::to_string(kMaxSamplesPerPixel))
                                     .c_str(),
                                 v);
             }
             s.out.firstSample = static_cast<uint32_t>(a);
             s.out.settings.samplesPerPixel = b;
             return {};
         }},
        {"--partial", "FILE.exr", kRender,
         "write the unnormalised sums and their sample range for raylab-merge (-o optional)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (lowerCase(v).size() < 5 ||
                 lowerCase(v).substr(lowerCase(v).size() - 4) != ".exr") {
                 return expected("a file name ending in .exr", v);
             }
             s.out.partial = v;
             return {};
         }},
        {"--crop", "X0,Y0,X1,Y1", kRender,
         "render only the pixels X0 <= x < X1, Y0 <= y < Y1 of the image",
         [](const std::string& v, ParseState& s) -> std::string {
             int values[4] = {-1, -1, -1, -1};
             std::size_t start = 0;
             for (int k = 0; k < 4; ++k) {
                 const std::size_t comma = k < 3 ? v.find(',', start) : v.size();
                 if (comma == std::string::npos ||
                     !parseInt(v.substr(start, comma - start), values[k]) || values[k] < 0) {
                     return expected("four integers x0,y0,x1,y1 >= 0", v);
                 }
                 start = comma + 1;
             }
             if (values[2] <= values[0] || values[3] <= values[1]) {
                 return expected("a rectangle with x0 < x1 and y0 < y1", v);
             }
             s.out.crop = FilmWindow{values[0], values[1], values[2], values[3]};
             return {};
         }},
        {"--turntable", "N", kRender,
         "the frames of a turntable: N cameras turning about the scene's centre",
         intIn(1, static_cast<int>(kMaxFrames), &CommandLine::turntable)},
        {"--frames-from", "FILE.json", kRender,
         "the frames' cameras from a settings file's \"frames\" (--save-frames writes one)",
         [](const std::string& v, ParseState& s) -> std::string {
             RenderSettings ignored;
             SettingsJsonExtras extras;
             std::string error;
             if (!loadSettingsFile(v, ignored, extras, error)) {
                 return error;
             }
             if (extras.frames.empty()) {
                 return v + " lists no \"frames\"";
             }
             s.out.frameCameras = std::move(extras.frames);
             return {};
         }},
        {"--frame", "K", kRender, "render frame K (from 0) of --turntable or --frames-from",
         intIn(0, static_cast<int>(kMaxFrames) - 1, &CommandLine::frame)},
        {"--save-frames", "FILE.json", kRender,
         "write the settings with the frames' cameras, for --frames-from (-o optional)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (v.empty()) {
                 return "expected a file name";
             }
             s.out.saveFrames = v;
             return {};
         }},
        {"--inspect", "X,Y", kRender,
         "print the lab's equation for pixel X,Y with its numbers, as JSON (-o optional)",
         [](const std::string& v, ParseState& s) -> std::string {
             const std::size_t comma = v.find(',');
             int x = -1;
             int y = -1;
             if (comma == std::string::npos || !parseInt(v.substr(0, comma), x) ||
                 !parseInt(v.substr(comma + 1), y) || x < 0 || y < 0) {
                 return expected("a pixel x,y of two integers >= 0", v);
             }
             s.out.inspect = true;
             s.out.inspectX = x;
             s.out.inspectY = y;
             return {};
         }},
        {"--split", "D", kViewer,
         "start with the A/B split: left this integrator, right the other, the divider at D "
         "(0..1)",
         [](const std::string& v, ParseState& s) -> std::string {
             float d = 0.0f;
             if (!parseFloat(v, d) || d < 0.0f || d > 1.0f) {
                 return expected("a divider position in [0, 1]", v);
             }
             s.out.split = d;
             return {};
         }},
        {"--frames", "N", kViewer, "quit after N frames (0 = run until closed)",
         intIn(0, 1 << 30, &CommandLine::frames)},
        {"--frames", "N", kBench, "best of N timed frames (default 5)",
         intIn(1, 1 << 20, &CommandLine::benchFrames)},
        {"--screenshot", "FILE", kViewer, "save the last shown frame (.png, .pfm or .exr)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!isSupportedImagePath(v)) {
                 return unsupportedImageReason(v);
             }
             s.out.screenshot = v;
             return {};
         }},
        {"--screenshot-dir", "DIR", kViewer, "folder for screenshots taken with a key (default .)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (v.empty()) {
                 return "expected a folder";
             }
             s.out.screenshotDir = v;
             return {};
         }},
        {"--no-panel", nullptr, kViewer, "start with the panel hidden (F1 toggles it)",
         [](const std::string&, ParseState& s) -> std::string {
             s.out.viewer.showPanel = false;
             return {};
         }},
        {"--resolution-scale", "S", kViewer,
         "render at the picture's size times S, 0.1..1 (default 1)",
         viewerScale(0.1f, 1.0f, &ViewerFlags::resolutionScale)},
        {"--ui-scale", "S", kViewer,
         "the panel's scale (font and sizes), 0.5..4, instead of the monitor's content scale",
         viewerScale(kMinUiScale, kMaxUiScale, &ViewerFlags::uiScale)},
        {"--readback", "FILE", kViewer,
         "test mode: with --frames, also save what the window shows (read back from the GL "
         "framebuffer) of the last frame as PNG",
         viewerFile(&ViewerFlags::readback)},
        {"--stats", "FILE", kViewer,
         "on quitting, write the window's frame rate, the tracer's pass times and the panel's "
         "last readouts (JSON) to FILE",
         viewerFile(&ViewerFlags::stats)},
        {"--drop", "FILE", kViewer,
         "once the window shows, act as if FILE were dropped on it (a mesh opens; a raylab "
         "screenshot's .png or .json restores it)",
         viewerFile(&ViewerFlags::drop)},
        {"--record", "FILE.json", kViewer,
         "on quitting, write every change of settings, view, inspection and screenshot, with its "
         "frame, to FILE.json",
         viewerFile(&ViewerFlags::record)},
        {"--replay", "FILE.json", kViewer,
         "play a recorded session back in the window, writing each of its screenshots again (to "
         "--screenshot-dir), then quit",
         viewerFile(&ViewerFlags::replay)},
        {"--json", nullptr, kBench, "print the results as JSON",
         [](const std::string&, ParseState& s) -> std::string {
             s.out.json = true;
             return {};
         }},
        {"--workload", "primary|bounce", kBench,
         "primary: a camera ray per pixel and a shadow ray per lit hit (default); bounce: also "
         "a diffuse bounce ray per hit",
         [](const std::string& v, ParseState& s) -> std::string {
             if (v != "primary" && v != "bounce") {
                 return expected("primary or bounce", v);
             }
             s.out.bench.bounceWorkload = v == "bounce";
             return {};
         }},
        {"--scalar", nullptr, kBench, "raylab's scalar reference traversal (binary BVH)",
         benchSwitch(&BenchOptions::scalar)},
        {"--no-packets", nullptr, kBench, "single rays only (no 8-ray packets, no blocks)",
         benchSwitch(&BenchOptions::noPackets)},
        {"--no-blocks", nullptr, kBench, "no 8x8 pixel blocks through frustum candidates",
         benchSwitch(&BenchOptions::noBlocks)},
        {"--no-passes", nullptr, kBench, "no renderer passes (lab and path integrators' samples/s)",
         benchSwitch(&BenchOptions::noPasses)},
        {"--spatial-budget", "F", kBench, "BVH spatial splits: extra references, fraction 0 to 1",
         benchFraction(&BenchOptions::spatialBudget, 1.0f)},
        {"--spatial-min-gain", "F", kBench,
         "BVH spatial splits: kept where the SAH cost falls by F times the fraction of "
         "references added, F >= 0",
         benchFraction(&BenchOptions::spatialMinGain)},
        {"--presplit-budget", "F", kBench, "BVH pre-splitting: extra references, fraction >= 0",
         benchFraction(&BenchOptions::presplitBudget)},
        {"--embree-isa", "NAME", kBench,
         "Embree's instruction set: sse2, sse4.2, avx or avx2 (default: Embree's own choice, its "
         "widest)",
         [](const std::string& v, ParseState& s) -> std::string {
             if (!isEmbreeIsa(v)) {
                 return expected("sse2, sse4.2, avx or avx2", v);
             }
             s.out.bench.embreeIsa = v;
             return {};
         }},
        {"--no-embree", nullptr, kBench, "skip Embree", benchSwitch(&BenchOptions::noEmbree)},
        {"--help", nullptr, kAll, "show this help", nullptr},
    };
    return table;
}

const Option* findOption(const std::string& name, Program program) {
    const std::string canonical = name == "--output" ? "-o" : name;
    for (const Option& option : options()) {
        if (canonical == option.name && (option.programs & maskOf(program)) != 0) {
            return &option;
        }
    }
    return nullptr;
}

struct Word {
    const Option* option;
    std::string name; // as written, for messages
    std::string value;
};

void markGivenFromKeys(const SettingsJsonExtras& extras, GivenSettings& given) {
    auto has = [&](const char* key) { return extras.keys.count(key) != 0; };
    given.cameraPosition |= has("camera.position");
    given.cameraYaw |= has("camera.yaw");
    given.cameraPitch |= has("camera.pitch");
    given.cameraFov |= has("camera.fov");
    given.lightPosition |= has("light.position");
    given.lightColor |= has("light.color");
    given.lightIntensity |= has("light.intensity");
    given.shadowEpsilon |= has("shadows.epsilon");
}

const char* programName(Program program) {
    switch (program) {
    case Program::Render: return "raylab-render";
    case Program::Viewer: return "raylab";
    case Program::Bench: return "raylab-bench";
    }
    return "raylab";
}

} // namespace

int parseCommandLine(int argc, const char* const* argv, Program program, CommandLine& out,
                     std::string& error) {
    const SingleLineOnExit oneLine(error);
    CommandLine result;
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) {
        args.emplace_back(argv[i] != nullptr ? argv[i] : "");
    }
    for (const std::string& arg : args) {
        if (arg == "--") {
            break;
        }
        if (arg == "--help" || arg == "-h") {
            result.help = true;
            out = std::move(result);
            return 0;
        }
    }

    // Pass 1: words to options and values.
    std::vector<Word> words;
    std::string settingsFile;
    bool sceneGiven = false;
    bool optionsEnded = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (!optionsEnded && arg == "--") {
            optionsEnded = true;
            continue;
        }
        if (!optionsEnded && arg.size() > 1 && arg[0] == '-') {
            const std::size_t eq = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
            const std::string name = arg.substr(0, eq);
            const Option* option = findOption(name, program);
            if (option == nullptr) {
                error = "unknown option " + quoted(name) + " (see --help)";
                return 2;
            }
            std::string value;
            if (option->argument == nullptr) {
                if (eq != std::string::npos) {
                    error = "option " + quoted(name) + " takes no value";
                    return 2;
                }
            } else if (eq != std::string::npos) {
                value = arg.substr(eq + 1);
            } else if (i + 1 < args.size()) {
                value = args[++i];
            } else {
                error = "option " + quoted(name) + " needs a value (" + option->argument + ")";
                return 2;
            }
            if (std::string(option->name) == "--settings") {
                if (value.empty()) {
                    error = "option '--settings' needs a file name";
                    return 2;
                }
                settingsFile = value; // the last one counts
            } else {
                words.push_back({option, name, value});
            }
            continue;
        }
        if (sceneGiven) {
            error = "unexpected argument " + quoted(arg) + " (one SCENE at most; see --help)";
            return 2;
        }
        if (arg.empty()) {
            error = "empty SCENE argument";
            return 2;
        }
        result.scene = arg;
        sceneGiven = true;
    }

    // The settings file first, whatever its position; the flags then override it.
    if (!settingsFile.empty()) {
        SettingsJsonExtras extras;
        if (!loadSettingsFile(settingsFile, result.settings, extras, error)) {
            return 1;
        }
        markGivenFromKeys(extras, result.given);
        result.bookmarks = extras.bookmarks;
        result.observedLabCamera = extras.observedLabCamera;
        result.frameCameras = extras.frames;
        if (!sceneGiven && !extras.scene.empty()) {
            result.scene = extras.scene;
        }
    }

    // Each program's defaults where neither a flag nor (for the viewer) the settings file gave
    // them.
    const auto given = [&words](std::initializer_list<const char*> names) {
        return std::any_of(words.begin(), words.end(), [&](const Word& w) {
            return std::any_of(names.begin(), names.end(),
                               [&](const char* n) { return std::string(w.option->name) == n; });
        });
    };
    if (program == Program::Bench && !given({"--width", "--height"})) {
        result.settings.width = kBenchWidth;
        result.settings.height = kBenchHeight;
    }
    if (program == Program::Viewer && settingsFile.empty()) {
        if (!given({"--spp"})) {
            result.settings.samplesPerPixel = kViewerSampleCap;
        }
        if (!given({"--width", "--height"})) {
            result.settings.width = kViewerWidth;
            result.settings.height = kViewerHeight;
        }
    }

    // Pass 2: every other option, in order.
    // Each value is checked where it is given (so the error names the flag), then the whole set
    // with core validate() after each option, which catches the limits the flags do not repeat.
    ParseState state{result, program, std::nullopt, false};
    const bool startedValid = validate(result.settings).empty();
    for (const Word& word : words) {
        if (std::string why = word.option->handle(word.value, state); !why.empty()) {
            error = word.name + ": " + why;
            return 2;
        }
        if (std::string why = validate(result.settings); startedValid && !why.empty()) {
            error = word.name + ": " + why;
            return 2;
        }
    }
    if (state.focal && state.fovFlag) {
        error = "--fov and --focal both set the field of view; give one";
        return 2;
    }
    if (state.focal) {
        // The focal length is in pixels of the final image height.
        const float fov = verticalFovFromFocal(*state.focal, result.settings.height);
        if (!std::isfinite(fov) || fov <= 0.0f || fov >= 180.0f) {
            error = "--focal: gives no usable field of view for height " +
                    std::to_string(result.settings.height);
            return 2;
        }
        result.settings.camera.verticalFovDegrees = fov;
    }
    if (program == Program::Render && result.output.empty() && !result.inspect &&
        result.partial.empty() && result.saveFrames.empty()) {
        error = "missing output file (-o FILE or --partial FILE.exr; see --help)";
        return 2;
    }
    if (!result.viewer.record.empty() && !result.viewer.replay.empty()) {
        error = "--record and --replay: give one (a replay plays a recording as it was)";
        return 2;
    }
    if (!result.viewer.replay.empty() && result.frames > 0) {
        error = "--replay plays the recording's own frames; --frames does not apply";
        return 2;
    }
    if (!result.viewer.readback.empty() && result.frames <= 0) {
        error = "--readback needs --frames N";
        return 2;
    }
    if (!result.saveFrames.empty() && result.turntable == 0 && result.frameCameras.empty()) {
        error = "--save-frames: no frames to save (give --turntable N or --frames-from FILE)";
        return 2;
    }
    if (result.firstSample >= static_cast<uint32_t>(result.settings.samplesPerPixel)) {
        error = "--samples: the range starts at " + std::to_string(result.firstSample) +
                " but --spp ends it at " + std::to_string(result.settings.samplesPerPixel);
        return 2;
    }
    if (result.crop &&
        (result.crop->x1 > result.settings.width || result.crop->y1 > result.settings.height)) {
        error = "--crop: " + std::to_string(result.crop->x0) + "," +
                std::to_string(result.crop->y0) + "," + std::to_string(result.crop->x1) + "," +
                std::to_string(result.crop->y1) + " is not inside the " +
                std::to_string(result.settings.width) + "x" +
                std::to_string(result.settings.height) + " image";
        return 2;
    }
    if (result.inspect &&
        (result.inspectX >= result.settings.width || result.inspectY >= result.settings.height)) {
        error = "--inspect: pixel " + std::to_string(result.inspectX) + "," +
                std::to_string(result.inspectY) + " is outside the " +
                std::to_string(result.settings.width) + "x" +
                std::to_string(result.settings.height) + " image";
        return 2;
    }
    if (std::string why = validate(result.settings); !why.empty()) {
        error = why;
        return 2;
    }
    result.cameraGiven =
        result.given.cameraPosition || result.given.cameraYaw || result.given.cameraPitch;
    result.lightGiven = result.given.lightPosition;
    result.shadowEpsilonGiven = result.given.shadowEpsilon;
    out = std::move(result);
    return 0;
}

bool isEmbreeIsa(const std::string& isa) {
    return isa == "sse2" || isa == "sse4.2" || isa == "avx" || isa == "avx2";
}

std::string usage(Program program) {
    std::ostringstream text;
    text << "usage: " << programName(program) << " [SCENE] [options]";
    if (program == Program::Render) {
        text << " -o FILE";
    }
    text
        << "\n\nSCENE is a mesh file (OBJ, PLY, glTF/GLB, or anything Assimp reads) or the built-in"
           "\n'cornell' (the default). A mesh with no camera or light given is framed.\n"
           "Values: --flag VALUE or --flag=VALUE. --settings is applied first; flags override it."
           "\n\noptions:\n";
    for (const Option& option : options()) {
        if ((option.programs & maskOf(program)) == 0) {
            continue;
        }
        std::string left = std::string("  ") + option.name;
        if (option.argument != nullptr) {
            left += std::string(" ") + option.argument;
        }
        left.resize(std::max<std::size_t>(left.size() + 2, 26), ' ');
        text << left << option.help << "\n";
    }
    if (program == Program::Bench) {
        text << "\nraylab-bench traces " << kBenchWidth << "x" << kBenchHeight
             << " unless --width or --height is given.\n";
    } else {
        if (program == Program::Viewer) {
            text << "\nThe picture is " << kViewerWidth << "x" << kViewerHeight
                 << " unless --width, --height or --settings gives it; the window adds the\n"
                    "panel's column beside it. The sample cap is --spp (default "
                 << kViewerSampleCap
                 << "). With --frames N and\n"
                    "--screenshot or --readback, the viewer shows at least N frames and keeps "
                    "going until the\n"
                    "picture has reached the sample cap, then saves and quits.\n"
                    "Keys: Up/Down move, Left/Right turn, W/S A/D Q/E move the light, mouse drag "
                    "turns, wheel\n"
                    "moves, F12 screenshot, F1 panel, Escape quits (or cancels a scene load); H "
                    "in the window\n"
                    "lists every key. A key press moves one step; a key held longer than 0.25 s "
                    "moves smoothly,\n"
                    "25 steps a second, until released. Dropping a mesh file on the window opens "
                    "it; dropping a\n"
                    "raylab screenshot (.png or .json) restores its scene and settings.\n";
        }
        text << "\nthe lab's steps (--preset NAME):\n";
        for (const LabPreset& preset : labPresets()) {
            text << "  " << preset.name << ": " << preset.shows << "; " << preset.equation << "\n";
        }
    }
    return text.str();
}

std::string finishSettings(const Scene& scene, CommandLine& commandLine) {
    RenderSettings& settings = commandLine.settings;
    placeForScene(scene, isLabBoxName(commandLine.scene), commandLine.given, settings);
    if (commandLine.lookAt) {
        lookAt(settings.camera, *commandLine.lookAt);
    }
    if (commandLine.turntable > 0) {
        commandLine.frameCameras =
            turntableCameras(settings.camera, scene.bounds().center(), commandLine.turntable);
    }
    if (commandLine.frame >= 0) {
        if (static_cast<std::size_t>(commandLine.frame) >= commandLine.frameCameras.size()) {
            return "--frame " + std::to_string(commandLine.frame) + ": " +
                   (commandLine.frameCameras.empty()
                        ? std::string("no frames (give --turntable N or --frames-from FILE)")
                        : "there are " + std::to_string(commandLine.frameCameras.size()) +
                              " frames");
        }
        settings.camera = commandLine.frameCameras[static_cast<std::size_t>(commandLine.frame)];
    }
    return validate(settings);
}

} // namespace raylab
