#include "bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace raylab::bench {

namespace {

double mrays(const BenchReport& r, double seconds) {
    return seconds > 0.0 ? static_cast<double>(r.primaryRays + r.shadowRays) / seconds * 1e-6 : 0.0;
}

double percent(std::size_t part, std::size_t whole) {
    return whole > 0 ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

std::string format(const char* pattern, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

// A JSON string literal (escapes quotes, backslashes and control characters).
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(c));
            out += buffer;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

void printFigures(std::ostream& out, const char* name, const BenchReport& r,
                  const TracerFigures& f) {
    out << name << "  1 thread: " << format("%7.2f", mrays(r, f.one.bestSeconds)) << " Mrays/s "
        << format("%8.2f", f.one.bestSeconds * 1e3) << " ms/frame   " << r.threads
        << " threads: " << format("%7.2f", mrays(r, f.all.bestSeconds)) << " Mrays/s "
        << format("%8.2f", f.all.bestSeconds * 1e3) << " ms/frame   build "
        << format("%.1f", f.buildSeconds * 1e3) << " ms\n";
}

void jsonFigures(std::ostream& out, const BenchReport& r, const TracerFigures& f) {
    out << "{\"build_ms\": " << format("%.3f", f.buildSeconds * 1e3)
        << ", \"one_thread\": {\"mrays_per_s\": " << format("%.3f", mrays(r, f.one.bestSeconds))
        << ", \"frame_ms\": " << format("%.3f", f.one.bestSeconds * 1e3)
        << "}, \"all_threads\": {\"mrays_per_s\": " << format("%.3f", mrays(r, f.all.bestSeconds))
        << ", \"frame_ms\": " << format("%.3f", f.all.bestSeconds * 1e3) << "}}";
}

} // namespace

std::size_t countDisagreeingHits(const std::vector<Hit>& a, const std::vector<Hit>& b) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        if (a[i].triangle == b[i].triangle) {
            continue;
        }
        const bool bothFound = a[i].found() && b[i].found();
        const float scale = std::max(std::fabs(a[i].t), std::fabs(b[i].t));
        if (!bothFound || !(std::fabs(a[i].t - b[i].t) <= 1e-4f * scale)) {
            ++count;
        }
    }
    return count;
}

void printText(std::ostream& out, const BenchReport& r) {
    out << "scene " << r.scene << ": " << r.triangles << " triangles (" << r.skipped
        << " skipped), " << r.width << "x" << r.height << ", " << r.primaryRays << " primary + "
        << r.shadowRays << " shadow rays, best of " << r.frames << " frames\n";
    out << "raylab BVH: " << r.traversal << ", depth " << r.bvhDepth << ", "
        << format("%.2f", static_cast<double>(r.bvhBytes) / (1024.0 * 1024.0)) << " MiB, "
        << r.leafReferences << " leaf triangles\n";
    if (r.packets) {
        printFigures(out, "raylab (packets)", r, r.raylab);
        if (r.blocks) {
            printFigures(out, "raylab (blocks) ", r, r.raylabBlocks);
        }
        printFigures(out, "raylab (1 ray)  ", r, r.raylabSingle);
        out << "packets / single rays: "
            << format("%.2f", r.raylabSingle.one.bestSeconds / r.raylab.one.bestSeconds)
            << " (1 thread), "
            << format("%.2f", r.raylabSingle.all.bestSeconds / r.raylab.all.bestSeconds) << " ("
            << r.threads << " threads); answers differing: " << r.packetMismatches << "\n";
        if (r.blocks) {
            out << "blocks / packets: "
                << format("%.2f", r.raylab.one.bestSeconds / r.raylabBlocks.one.bestSeconds)
                << " (1 thread), "
                << format("%.2f", r.raylab.all.bestSeconds / r.raylabBlocks.all.bestSeconds) << " ("
                << r.threads << " threads); answers differing from packets: " << r.blockMismatches
                << "\n";
            out << "blocks through frustum candidates: camera " << r.cameraBlocksThroughCandidates
                << " of " << r.cameraBlocks << " ("
                << format("%.1f", percent(r.cameraBlocksThroughCandidates, r.cameraBlocks))
                << "%), shadow " << r.shadowBlocksThroughCandidates << " of " << r.shadowBlocks
                << " (" << format("%.1f", percent(r.shadowBlocksThroughCandidates, r.shadowBlocks))
                << "%)\n";
        }
    } else {
        printFigures(out, "raylab", r, r.raylab);
    }
    if (!r.hasEmbree) {
        out << "Embree: " << r.embreeAbsent << "\n";
        return;
    }
    printFigures(out, r.packets ? "Embree          " : "Embree", r, r.embree);
    out << "raylab / Embree: "
        << format("%.2f", r.embree.one.bestSeconds / r.raylab.one.bestSeconds) << " (1 thread), "
        << format("%.2f", r.embree.all.bestSeconds / r.raylab.all.bestSeconds) << " (" << r.threads
        << " threads)\n";
    if (r.blocks) {
        out << "raylab blocks / Embree: "
            << format("%.2f", r.embree.one.bestSeconds / r.raylabBlocks.one.bestSeconds)
            << " (1 thread), "
            << format("%.2f", r.embree.all.bestSeconds / r.raylabBlocks.all.bestSeconds) << " ("
            << r.threads << " threads)\n";
    }
    out << "closest hits disagreeing with Embree: " << r.disagreeingHits << " of " << r.primaryRays
        << "; shadow rays disagreeing: " << r.disagreeingShadows << " of " << r.shadowRays << "\n";
}

void printJson(std::ostream& out, const BenchReport& r) {
    out << "{\"scene\": " << quoted(r.scene) << ", \"triangles\": " << r.triangles
        << ", \"skipped_triangles\": " << r.skipped << ", \"width\": " << r.width
        << ", \"height\": " << r.height << ", \"threads\": " << r.threads
        << ", \"frames\": " << r.frames << ", \"primary_rays\": " << r.primaryRays
        << ", \"shadow_rays\": " << r.shadowRays << ",\n \"raylab\": ";
    jsonFigures(out, r, r.raylab);
    out << ", \"packets\": " << (r.packets ? "true" : "false");
    if (r.packets) {
        out << ",\n \"raylab_single_ray\": ";
        jsonFigures(out, r, r.raylabSingle);
        out << ", \"packet_mismatches\": " << r.packetMismatches;
    }
    out << ", \"blocks\": " << (r.blocks ? "true" : "false");
    if (r.blocks) {
        out << ",\n \"raylab_blocks\": ";
        jsonFigures(out, r, r.raylabBlocks);
        out << ", \"block_mismatches\": " << r.blockMismatches
            << ",\n \"camera_blocks\": " << r.cameraBlocks
            << ", \"camera_blocks_through_candidates\": " << r.cameraBlocksThroughCandidates
            << ", \"camera_candidate_fraction\": "
            << format("%.4f", percent(r.cameraBlocksThroughCandidates, r.cameraBlocks) / 100.0)
            << ", \"shadow_blocks\": " << r.shadowBlocks
            << ", \"shadow_blocks_through_candidates\": " << r.shadowBlocksThroughCandidates
            << ", \"shadow_candidate_fraction\": "
            << format("%.4f", percent(r.shadowBlocksThroughCandidates, r.shadowBlocks) / 100.0);
    }
    out << ",\n \"bvh\": {\"traversal\": " << quoted(r.traversal) << ", \"depth\": " << r.bvhDepth
        << ", \"memory_bytes\": " << r.bvhBytes << ", \"leaf_triangles\": " << r.leafReferences
        << "}";
    if (r.hasEmbree) {
        out << ",\n \"embree\": ";
        jsonFigures(out, r, r.embree);
        out << ",\n \"ratio_one_thread\": "
            << format("%.4f", r.embree.one.bestSeconds / r.raylab.one.bestSeconds)
            << ", \"ratio_all_threads\": "
            << format("%.4f", r.embree.all.bestSeconds / r.raylab.all.bestSeconds)
            << ", \"disagreeing_hits\": " << r.disagreeingHits
            << ", \"disagreeing_shadow_rays\": " << r.disagreeingShadows;
        if (r.blocks) {
            out << ", \"blocks_ratio_one_thread\": "
                << format("%.4f", r.embree.one.bestSeconds / r.raylabBlocks.one.bestSeconds)
                << ", \"blocks_ratio_all_threads\": "
                << format("%.4f", r.embree.all.bestSeconds / r.raylabBlocks.all.bestSeconds);
        }
    } else {
        out << ",\n \"embree\": null";
    }
    out << "}\n";
}

} // namespace raylab::bench
