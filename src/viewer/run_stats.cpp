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
    const auto perSecond = [&stats](uint64_t count) {
        return stats.shownSeconds > 0.0 ? static_cast<double>(count) / stats.shownSeconds : 0.0;
    };
    // Frames: the first swap starts the clock, so the rate counts the intervals after it.
    const double fps = stats.framesShown > 1 ? perSecond(stats.framesShown - 1) : 0.0;
    nlohmann::ordered_json json = {
        {"redraw", stats.continuous ? "continuous" : "on demand"},
        {"frames_shown", stats.framesShown},
        {"seconds", stats.shownSeconds},
        {"window_fps", fps},
        {"pictures_shown", stats.uploads.count},
        {"pictures_per_second", perSecond(stats.uploads.count)},
        {"views_shown", stats.viewsShown},
        {"views_per_second", perSecond(stats.viewsShown)},
        {"frame_ms",
         {{"mean", stats.frameResponses.mean() * 1000.0},
          {"max", stats.frameResponses.max * 1000.0}}},
        {"frames_over_33ms", stats.slowFrames},
        {"draw_ms",
         {{"mean", stats.drawTimes.mean() * 1000.0}, {"max", stats.drawTimes.max * 1000.0}}},
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
    if (stats.hover) {
        const PixelReadout& h = *stats.hover;
        json["hover"] = {{"pixel", {h.x, h.y}},
                         {"linear", {h.linear.x, h.linear.y, h.linear.z}},
                         {"display", {h.display[0], h.display[1], h.display[2]}}};
    }
    if (stats.rectangle) {
        const RectangleMean& r = *stats.rectangle;
        json["rectangle"] = {{"from", {r.rectangle.x0, r.rectangle.y0}},
                             {"to", {r.rectangle.x1, r.rectangle.y1}},
                             {"pixels", r.pixels},
                             {"mean", {r.mean.x, r.mean.y, r.mean.z}}};
    }
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
