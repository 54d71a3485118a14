#include "run_stats.h"

#include "io/atomic_file.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace raylab::viewer {

namespace {

nlohmann::ordered_json milliseconds(const Tally& tally) {
    return {
        {"mean", tally.mean() * 1000.0}, {"min", tally.min * 1000.0}, {"max", tally.max * 1000.0}};
}

} // namespace

void Tally::add(double value) {
    min = count == 0 ? value : std::min(min, value);
    max = count == 0 ? value : std::max(max, value);
    sum += value;
    ++count;
}

std::string runStatsJson(const RunStats& stats) {
    const double fps = stats.shownSeconds > 0.0 && stats.framesShown > 1
                           ? static_cast<double>(stats.framesShown - 1) / stats.shownSeconds
                           : 0.0;
    nlohmann::ordered_json json = {
        {"frames_shown", stats.framesShown},
        {"seconds", stats.shownSeconds},
        {"window_fps", fps},
        {"frame_ms",
         {{"mean", stats.frameIntervals.mean() * 1000.0},
          {"max", stats.frameIntervals.max * 1000.0}}},
        {"frames_over_33ms", stats.slowFrames},
        {"minimised_seconds", stats.minimisedSeconds},
        {"upload_ms",
         {{"count", stats.uploads.count},
          {"mean", stats.uploads.mean() * 1000.0},
          {"max", stats.uploads.max * 1000.0}}},
        {"passes", stats.tracer.passes.count},
        {"pass_ms", milliseconds(stats.tracer.passes)},
        {"previews", stats.tracer.previews.count},
        {"preview_ms", milliseconds(stats.tracer.previews)},
        {"cancelled_passes", stats.tracer.cancelled},
        {"samples", stats.samples},
        {"render_width", stats.width},
        {"render_height", stats.height},
        {"scene", stats.scene},
        {"triangles", stats.triangles},
    };
    return json.dump(2) + "\n";
}

bool writeRunStats(const std::string& path, const RunStats& stats, std::string& error) {
    const std::string text = runStatsJson(stats);
    return writeFileAtomically(
        path,
        [&text](std::FILE* file, std::string& why) {
            if (std::fwrite(text.data(), 1, text.size(), file) != text.size()) {
                why = "cannot write";
                return false;
            }
            return true;
        },
        error);
}

} // namespace raylab::viewer
