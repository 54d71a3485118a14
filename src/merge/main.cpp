// raylab-merge: adds up partial renders (raylab-render --partial) into the picture one machine
// would have made. Checks that the parts share their settings, picture size and scene (by the
// hash of its file), and that they cover samples 0..N-1 of every pixel exactly once; otherwise it
// names what is missing or doubled, exits 1 and writes nothing. Exit codes: 0 done, 2 usage
// error, 1 anything else; every error is one line on stderr.

#include "core/render/film_merge.h"
#include "core/render_settings.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/partial_file.h"
#include "io/render_report.h"
#include "io/settings_json.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

namespace {

constexpr const char* kProgram = "raylab-merge";

constexpr const char* kUsage =
    "usage: raylab-merge PARTS... -o OUT\n"
    "\n"
    "Adds partial renders written by raylab-render --partial FILE.exr (sample ranges and crops\n"
    "of one picture) into the picture raylab-render --spp N would have made, bit for bit.\n"
    "OUT is .png (8-bit, the parts' display transform), .pfm or .exr (linear).\n"
    "\n"
    "options:\n"
    "  -o FILE                 the merged picture\n"
    "  --help                  show this help\n";

int fail(int code, const std::string& message) {
    std::fprintf(stderr, "%s: %s\n", kProgram, message.c_str());
    return code;
}

int run(int argc, char** argv) {
    std::vector<std::string> inputs;
    std::string output;
    bool optionsEnded = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (!optionsEnded && (arg == "--help" || arg == "-h")) {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (!optionsEnded && arg == "--") {
            optionsEnded = true;
        } else if (!optionsEnded && (arg == "-o" || arg == "--output")) {
            if (i + 1 >= argc) {
                return fail(2, "option '" + arg + "' needs a value (FILE)");
            }
            output = argv[++i];
        } else if (!optionsEnded && arg.rfind("--output=", 0) == 0) {
            output = arg.substr(9);
        } else if (!optionsEnded && arg.size() > 1 && arg[0] == '-') {
            return fail(2, "unknown option '" + arg + "' (see --help)");
        } else {
            inputs.push_back(arg);
        }
    }
    if (output.empty()) {
        return fail(2, "missing output file (-o FILE; see --help)");
    }
    if (!raylab::isSupportedImagePath(output)) {
        return fail(2, "-o: " + raylab::unsupportedImageReason(output));
    }
    if (inputs.empty()) {
        return fail(2, "no partial renders given (see --help)");
    }
    std::string error;
    if (!raylab::checkWritable(output, error)) {
        return fail(1, error);
    }

    std::vector<raylab::PartialRender> parts(inputs.size());
    raylab::RenderSettings settings;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        // Headers first: a merge of many large parts holds one part's pixels at a time.
        if (!raylab::readPartial(inputs[i], parts[i], error, raylab::PartialRead::HeaderOnly)) {
            return fail(1, error);
        }
        raylab::RenderSettings partSettings;
        if (!raylab::settingsFromJson(parts[i].settingsJson, partSettings, error)) {
            return fail(1, "'" + inputs[i] + "': its settings: " + error);
        }
        if (i == 0) {
            settings = partSettings;
            continue;
        }
        const raylab::PartialRender& first = parts[0];
        if (parts[i].imageWidth != first.imageWidth || parts[i].imageHeight != first.imageHeight) {
            return fail(1, "'" + inputs[i] + "' is a part of a " +
                               std::to_string(parts[i].imageWidth) + "x" +
                               std::to_string(parts[i].imageHeight) + " picture, '" + inputs[0] +
                               "' of a " + std::to_string(first.imageWidth) + "x" +
                               std::to_string(first.imageHeight) + " one");
        }
        if (parts[i].sceneHash != first.sceneHash) {
            return fail(1, "'" + inputs[i] + "' rendered another scene than '" + inputs[0] + "' (" +
                               parts[i].scene + " vs " + first.scene + ")");
        }
        if (!raylab::sameSamples(partSettings, settings) ||
            partSettings.display != settings.display ||
            partSettings.exposure != settings.exposure) {
            std::string what;
            for (const std::string& d : raylab::settingsDifferences(settings, partSettings)) {
                if (d.rfind("samples", 0) != 0 && d.rfind("threads", 0) != 0) {
                    what += (what.empty() ? "" : ", ") + d;
                }
            }
            return fail(1, "'" + inputs[i] + "' has other settings than '" + inputs[0] + "' (" +
                               what + ")");
        }
    }

    std::vector<raylab::FilmPart> filmParts;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        filmParts.push_back(
            {inputs[i], parts[i].window, parts[i].firstSample, parts[i].endSample, {}, {}});
    }
    uint32_t samples = 0;
    if (const std::string why =
            raylab::checkFilmParts(parts[0].imageWidth, parts[0].imageHeight, filmParts, samples);
        !why.empty()) {
        return fail(1, why);
    }
    // Then the pixels, part by part in order of their first sample (so that the float noise
    // moments add in one order), each checked again against its header.
    std::vector<std::size_t> order(parts.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(), [&parts](std::size_t a, std::size_t b) {
        return parts[a].firstSample < parts[b].firstSample;
    });
    const bool squares = std::all_of(parts.begin(), parts.end(),
                                     [](const raylab::PartialRender& p) { return p.hasSquares; });
    raylab::FilmMerger merger(parts[0].imageWidth, parts[0].imageHeight, squares);
    for (const std::size_t i : order) {
        raylab::PartialRender pixels;
        if (!raylab::readPartial(inputs[i], pixels, error)) {
            return fail(1, error);
        }
        if (pixels.window != parts[i].window || pixels.firstSample != parts[i].firstSample ||
            pixels.endSample != parts[i].endSample) {
            return fail(1, "'" + inputs[i] + "' changed while it was merged");
        }
        raylab::FilmPart part = filmParts[i];
        part.sums = pixels.sums;
        part.squares = pixels.squares;
        merger.add(part);
    }
    raylab::Film film;
    merger.finish(samples, film);
    settings.samplesPerPixel = static_cast<int>(film.samples());
    const std::string json = raylab::settingsToJson(settings, parts[0].scene);
    if (!raylab::writeImage(output, film.mean(), settings.display, settings.exposure, error,
                            {{"Software", "raylab-merge"}, {"raylab settings", json}})) {
        return fail(1, error);
    }
    const std::string noiseText = raylab::noiseSuffix(film.noise());
    std::fprintf(stderr, "%s: %zu parts, %dx%d, %u spp%s -> %s\n", kProgram, parts.size(),
                 film.width(), film.height(), film.samples(), noiseText.c_str(), output.c_str());
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
