// raylab-render: the headless renderer. Parses the command line, loads the scene, renders, and
// writes the image by its extension. Exit codes: 0 done, 2 usage error, 1 anything else; every
// error is one line on stderr and leaves no output file behind.

#include "core/bvh/bvh.h"
#include "core/integrators/pixel_inspection.h"
#include "core/lights/emitters.h"
#include "core/render/film.h"
#include "core/render/image_error.h"
#include "core/render/renderer.h"
#include "io/atomic_file.h"
#include "io/command_line.h"
#include "io/image_io.h"
#include "io/inspection_json.h"
#include "io/load_progress.h"
#include "io/mesh_import.h"
#include "io/partial_file.h"
#include "io/render_report.h"
#include "io/settings_json.h"
#include "io/text_util.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <unistd.h>

namespace {

using raylab::CommandLine;
using Clock = std::chrono::steady_clock;

constexpr const char* kProgram = "raylab-render";

int fail(int code, const std::string& message) {
    std::fprintf(stderr, "%s: %s\n", kProgram, message.c_str());
    return code;
}

// "\rrendering 42%" on stderr, only when stderr is a terminal and the render has run for more
// than a second; erased when the render ends.
class ProgressLine {
public:
    ProgressLine() : enabled_(::isatty(STDERR_FILENO) == 1), start_(Clock::now()) {}
    ~ProgressLine() {
        if (shown_) {
            std::fputs("\r                \r", stderr);
            std::fflush(stderr);
        }
    }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void update(double fraction) {
        if (!enabled_ || Clock::now() - start_ < std::chrono::seconds(1)) {
            return;
        }
        const int percent = static_cast<int>(fraction * 100.0);
        if (percent != lastPercent_) {
            std::fprintf(stderr, "\rrendering %d%%", percent);
            std::fflush(stderr);
            lastPercent_ = percent;
            shown_ = true;
        }
    }

private:
    bool enabled_;
    Clock::time_point start_;
    bool shown_ = false;
    int lastPercent_ = -1;
};

// Reads a linear reference picture (.pfm or .exr) for --reference.
bool readReference(const std::string& path, raylab::Framebuffer& image, std::string& error) {
    const std::string lower = raylab::lowerCase(path);
    const auto endsWith = [&lower](const char* suffix) {
        const std::string end(suffix);
        return lower.size() >= end.size() &&
               lower.compare(lower.size() - end.size(), end.size(), end) == 0;
    };
    if (endsWith(".pfm")) {
        return raylab::readPfm(path, image, error);
    }
    if (endsWith(".exr")) {
        return raylab::readExr(path, image, error);
    }
    error = "reference '" + path + "': unsupported format (use .pfm or .exr)";
    return false;
}

// After `done` samples, the next count at which the error is measured (--reference: powers of
// two) or estimated (--target-error: powers of two and multiples of 64).
int nextCheck(int done) {
    if (done >= 64) {
        return (done / 64 + 1) * 64;
    }
    int next = 1;
    while (next <= done) {
        next *= 2;
    }
    return next;
}

int run(int argc, char** argv) {
    CommandLine cl;
    std::string error;
    if (const int code = raylab::parseCommandLine(argc, argv, raylab::Program::Render, cl, error);
        code != 0) {
        return fail(code, error);
    }
    if (cl.help) {
        std::fputs(raylab::usage(raylab::Program::Render).c_str(), stdout);
        return 0;
    }
    // Bad output paths fail now, not after the render.
    if (!cl.output.empty() && !raylab::checkWritable(cl.output, error)) {
        return fail(1, error);
    }
    if (!cl.saveSettings.empty() && !raylab::checkWritable(cl.saveSettings, error)) {
        return fail(1, error);
    }
    if (!cl.partial.empty() && !raylab::checkWritable(cl.partial, error)) {
        return fail(1, error);
    }
    if (!cl.saveFrames.empty() && !raylab::checkWritable(cl.saveFrames, error)) {
        return fail(1, error);
    }
    // A partial names its scene by the hash of its file's contents, so that raylab-merge can
    // tell that the parts rendered the same mesh.
    std::string sceneHash;
    if (!cl.partial.empty() && !raylab::sceneContentHash(cl.scene, sceneHash, error)) {
        return fail(1, error);
    }

    raylab::Scene scene;
    std::string warnings;
    bool loaded = false;
    {
        raylab::LoadProgressLine progress(kProgram, cl.scene); // erased at the end of this block
        loaded = raylab::loadScene(cl.scene, cl.importLimits, scene, warnings, error,
                                   progress.control());
    }
    if (!loaded) {
        return fail(1, error);
    }
    std::fputs(warnings.c_str(), stderr);
    if (const std::string why = raylab::finishSettings(scene, cl); !why.empty()) {
        return fail(1, why);
    }
    raylab::RenderSettings& settings = cl.settings;
    if (!cl.saveFrames.empty()) {
        raylab::SettingsFileExtras extras;
        extras.frames = cl.frameCameras;
        if (!raylab::saveSettingsFile(cl.saveFrames, settings, cl.scene, extras, error)) {
            return fail(1, error);
        }
        if (cl.output.empty() && cl.partial.empty() && !cl.inspect) {
            std::fprintf(stderr, "%s: %zu frames -> %s\n", kProgram, cl.frameCameras.size(),
                         cl.saveFrames.c_str());
            return 0;
        }
    }
    // The pixels rendered: the whole image, or --crop's window of it.
    const raylab::FilmWindow window =
        cl.crop.value_or(raylab::FilmWindow{0, 0, settings.width, settings.height});

    // --reference: the converged picture the samples' error is measured against, read first so
    // that a bad file fails before the render.
    raylab::Framebuffer reference;
    if (!cl.reference.empty()) {
        if (!readReference(cl.reference, reference, error)) {
            return fail(1, error);
        }
        if (reference.width != window.width() || reference.height != window.height()) {
            return fail(1,
                        "reference '" + cl.reference + "' is " + std::to_string(reference.width) +
                            "x" + std::to_string(reference.height) + ", the render is " +
                            std::to_string(window.width()) + "x" + std::to_string(window.height()));
        }
    }

    const auto buildStart = Clock::now();
    raylab::BvhBuildOptions bvhOptions;
    bvhOptions.threads = settings.threads;
    const raylab::Bvh bvh = raylab::buildBvh(scene, bvhOptions);
    const double buildSeconds = std::chrono::duration<double>(Clock::now() - buildStart).count();

    const raylab::EmitterTable emitters = raylab::buildEmitterTable(scene);
    if (cl.inspect) {
        const raylab::PixelInspection inspection =
            raylab::inspectPixel(scene, bvh, emitters, settings, cl.inspectX, cl.inspectY);
        std::printf("%s\n", raylab::inspectionToJson(inspection).c_str());
        std::fflush(stdout);
        if (cl.output.empty() && cl.partial.empty()) {
            return 0;
        }
    }

    const auto start = Clock::now();
    raylab::RayCounts counts;
    raylab::FilmLayers layers = raylab::filmLayersFor(settings);
    layers.moments = layers.moments || cl.targetError > 0.0f; // the noise estimate needs them
    layers.moments = layers.moments || !cl.partial.empty();   // a merge reports the noise
    raylab::Film film(window, layers);
    film.startAt(cl.firstSample);
    double referenceSeconds = 0.0; // time spent measuring errors, left out of the render's time
    {
        ProgressLine progress; // erased at the end of this block
        raylab::PassOptions passOptions;
        passOptions.emitters = &emitters;
        const int samples = settings.samplesPerPixel - static_cast<int>(cl.firstSample);
        const bool checks = !reference.pixels.empty() || cl.targetError > 0.0f;
        for (int done = 0; done < samples;) {
            // Passes of several samples (PassOptions::samples), ending where a check is due.
            int now = std::min(raylab::kSamplesPerPass, samples - done);
            if (checks) {
                now = std::min(now, nextCheck(done) - done);
            }
            passOptions.samples = static_cast<uint32_t>(now);
            passOptions.progress = [&progress, done, now, samples](double fraction) {
                progress.update((done + fraction * now) / samples);
            };
            raylab::renderPass(scene, bvh, settings, film, &counts, passOptions);
            done += now;
            if (!reference.pixels.empty() && ((done & (done - 1)) == 0 || done == samples)) {
                const auto measureStart = Clock::now();
                const double seconds =
                    std::chrono::duration<double>(measureStart - start).count() - referenceSeconds;
                const double rmse = raylab::relativeRmse(film.mean(), reference);
                std::printf("%d spp  relative RMSE %.6f  %.3f s\n", done, rmse, seconds);
                std::fflush(stdout);
                referenceSeconds +=
                    std::chrono::duration<double>(Clock::now() - measureStart).count();
            }
            // --target-error: stop once the estimated error is below it, checked at powers of
            // two and every 64 samples (each check reads the whole film).
            if (cl.targetError > 0.0f && done >= 2 &&
                ((done & (done - 1)) == 0 || done % 64 == 0)) {
                const auto measureStart = Clock::now();
                const raylab::NoiseEstimate noise = film.noise();
                referenceSeconds +=
                    std::chrono::duration<double>(Clock::now() - measureStart).count();
                if (noise.known && noise.relativeError < cl.targetError) {
                    break;
                }
            }
        }
    }
    // What the picture holds: --target-error may have stopped early, and the saved settings must
    // reproduce these bytes.
    settings.samplesPerPixel = static_cast<int>(film.nextSample());
    const double seconds =
        std::chrono::duration<double>(Clock::now() - start).count() - referenceSeconds;

    const std::string json = raylab::settingsToJson(settings, cl.scene);
    if (!cl.partial.empty()) {
        raylab::PartialRender partial = raylab::partialOf(film, settings.width, settings.height);
        partial.settingsJson = json;
        partial.scene = cl.scene;
        partial.sceneHash = sceneHash;
        if (!raylab::writePartial(cl.partial, partial, error)) {
            return fail(1, error);
        }
    }
    if (!cl.output.empty() &&
        !raylab::writeImage(cl.output, film.mean(), settings.display, settings.exposure, error,
                            {{"Software", "raylab-render"}, {"raylab settings", json}})) {
        return fail(1, error);
    }
    if (!cl.saveSettings.empty() &&
        !raylab::saveSettingsFile(cl.saveSettings, settings, cl.scene, error)) {
        return fail(1, error);
    }

    const double rays = static_cast<double>(counts.total());
    const double pixelSamples =
        static_cast<double>(film.samples()) * static_cast<double>(film.pixelCount());
    const std::string presetText = cl.preset ? ", preset " + std::string(cl.preset->name) + " (" +
                                                   std::string(cl.preset->equation) + ")"
                                             : std::string();
    const std::string noiseText = raylab::noiseSuffix(film.noise());
    const std::string samplesText = film.firstSample() == 0
                                        ? std::to_string(film.samples()) + " spp"
                                        : "samples " + std::to_string(film.firstSample()) + ":" +
                                              std::to_string(film.nextSample());
    const std::string sizeText =
        std::to_string(settings.width) + "x" + std::to_string(settings.height) +
        (cl.crop ? " crop " + std::to_string(window.x0) + "," + std::to_string(window.y0) + "," +
                       std::to_string(window.x1) + "," + std::to_string(window.y1)
                 : std::string());
    const std::string outputs =
        cl.output + (!cl.output.empty() && !cl.partial.empty() ? ", " : "") + cl.partial;
    std::fprintf(stderr,
                 "%s: %s, %s, %zu triangles, BVH %.2f s, render %.2f s, %.1f Mrays/s, "
                 "%.2f Msamples/s%s%s -> %s\n",
                 kProgram, sizeText.c_str(), samplesText.c_str(), scene.triangles.size(),
                 buildSeconds, seconds, seconds > 0.0 ? rays / seconds * 1e-6 : 0.0,
                 seconds > 0.0 ? pixelSamples / seconds * 1e-6 : 0.0, noiseText.c_str(),
                 presetText.c_str(), outputs.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        return fail(1, "out of memory");
    } catch (const std::exception& e) {
        return fail(1, e.what());
    }
}
