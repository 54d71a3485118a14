#include "bench_report.h"

#include "core/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace raylab::bench {

namespace {

struct EmbreeCallText {
    const char* key;   // the JSON key of its figures
    const char* label; // its row in the text table
    const char* call;  // what it calls, and how
};

// In EmbreeCall's order (embree_rays.h).
constexpr std::array<EmbreeCallText, kEmbreeCalls> kEmbreeCallText{{
    {"embree_single", "Embree rtcIntersect1", "rtcIntersect1/rtcOccluded1, incoherent"},
    {"embree_packet16", "Embree rtcIntersect16 4x4",
     "rtcIntersect16/rtcOccluded16 on 4x4 pixel tiles, coherent"},
    {"embree_stream", "Embree rtcIntersect1M 8x8",
     "rtcIntersect1M/rtcOccluded1M on 8x8 pixel tiles, coherent"},
}};

double percent(std::size_t part, std::size_t whole) {
    return whole > 0 ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

std::string format(const char* pattern, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

// How many times faster `a` is than `b` (b's best frame time over a's).
double speedup(const FrameTimes& a, const FrameTimes& b) {
    return a.bestSeconds > 0.0 ? b.bestSeconds / a.bestSeconds : 0.0;
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

// "1 thread" or "N threads": the report's thread count.
std::string threadsText(const BenchReport& r) {
    return std::to_string(r.threads) + (r.threads == 1 ? " thread" : " threads");
}

const char* workloadName(Workload w) { return w == Workload::Bounce ? "bounce" : "primary"; }

void printRow(std::ostream& out, const char* name, const TracerFigures& f) {
    char line[160];
    std::snprintf(line, sizeof line, "%-32s %9.2f %9.2f %9.2f %9.2f\n", name,
                  mraysPerSecond(f, f.one.bestSeconds), f.one.bestSeconds * 1e3,
                  mraysPerSecond(f, f.all.bestSeconds), f.all.bestSeconds * 1e3);
    out << line;
}

void printHeader(std::ostream& out, const BenchReport& r) {
    char line[160];
    std::snprintf(line, sizeof line, "%-32s %19s %19s\n%-32s %9s %9s %9s %9s\n", "", "1 thread",
                  threadsText(r).c_str(), "", "Mrays/s", "ms/frame", "Mrays/s", "ms/frame");
    out << line;
}

void printRatio(std::ostream& out, const char* what, const TracerFigures& a, const TracerFigures& b,
                const BenchReport& r) {
    out << what << ": " << format("%.2f", speedup(a.one, b.one)) << " (1 thread), "
        << format("%.2f", speedup(a.all, b.all)) << " (" << threadsText(r) << ")\n";
}

// {"build_ms": ..., "one_thread": {...}, "all_threads": {...}: the object stays open, so that the
// caller can add keys.
void jsonFiguresOpen(std::ostream& out, const TracerFigures& f) {
    out << "{\"build_ms\": " << format("%.3f", f.buildSeconds * 1e3) << ", \"rays\": " << f.rays
        << ", \"one_thread\": {\"mrays_per_s\": "
        << format("%.3f", mraysPerSecond(f, f.one.bestSeconds))
        << ", \"frame_ms\": " << format("%.3f", f.one.bestSeconds * 1e3)
        << "}, \"all_threads\": {\"mrays_per_s\": "
        << format("%.3f", mraysPerSecond(f, f.all.bestSeconds))
        << ", \"frame_ms\": " << format("%.3f", f.all.bestSeconds * 1e3) << "}";
}

void jsonFigures(std::ostream& out, const TracerFigures& f) {
    jsonFiguresOpen(out, f);
    out << "}";
}

// ", "ratio_one_thread": a over b, "ratio_all_threads": ...
void jsonRatios(std::ostream& out, const TracerFigures& a, const TracerFigures& b,
                const char* prefix = "") {
    out << ", \"" << prefix << "ratio_one_thread\": " << format("%.4f", speedup(a.one, b.one))
        << ", \"" << prefix << "ratio_all_threads\": " << format("%.4f", speedup(a.all, b.all));
}

// The best call's figures: on 1 thread those of one call, on all threads those of another.
TracerFigures bestFigures(const BenchReport& r) {
    TracerFigures best = r.embree[bestEmbreeCall(r, true)].figures;
    best.all = r.embree[bestEmbreeCall(r, false)].figures.all;
    return best;
}

void printEmbreeText(std::ostream& out, const BenchReport& r) {
    out << "Embree BVH (" << (r.embreeIsa.empty() ? "Embree's own ISA" : "isa=" + r.embreeIsa)
        << "): " << format("%.2f", static_cast<double>(r.embreeBytes) / (1024.0 * 1024.0))
        << " MiB ("
        << format("%.1f", static_cast<double>(r.embreeBytes) /
                              static_cast<double>(std::max<std::size_t>(1, r.triangles)))
        << " B/triangle) + geometry buffers "
        << format("%.2f", static_cast<double>(r.embreeGeometryBytes) / (1024.0 * 1024.0))
        << " MiB, build " << format("%.1f", r.embreeBuildSeconds * 1e3) << " ms (best of "
        << r.builds << "; the first " << format("%.1f", r.embreeFirstBuildSeconds * 1e3) << ")\n";
}

} // namespace

double mraysPerSecond(const TracerFigures& f, double seconds) {
    return seconds > 0.0 ? static_cast<double>(f.rays) / seconds * 1e-6 : 0.0;
}

std::size_t bestEmbreeCall(const BenchReport& report, bool one) {
    std::size_t best = 0;
    for (std::size_t c = 1; c < kEmbreeCalls; ++c) {
        const FrameTimes& t = one ? report.embree[c].figures.one : report.embree[c].figures.all;
        const FrameTimes& b =
            one ? report.embree[best].figures.one : report.embree[best].figures.all;
        best = t.bestSeconds < b.bestSeconds ? c : best;
    }
    return best;
}

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
        << " skipped), " << r.width << "x" << r.height << ", workload " << workloadName(r.workload)
        << ": " << r.primaryRays << " primary + " << r.shadowRays << " shadow";
    if (r.workload == Workload::Bounce) {
        out << " + " << r.bounceRays << " bounce";
    }
    out << " rays, best of " << r.frames << " frames\n";
    out << "raylab BVH: " << r.traversal << ", depth " << r.bvhDepth << ", "
        << format("%.2f", static_cast<double>(r.bvhBytes) / (1024.0 * 1024.0)) << " MiB ("
        << format("%.1f", static_cast<double>(r.bvhBytes) /
                              static_cast<double>(std::max<std::size_t>(1, r.triangles)))
        << " B/triangle), " << r.leafReferences << " leaf triangles, build "
        << format("%.1f", r.raylab.buildSeconds * 1e3) << " ms (best of " << r.builds
        << ", rebuilt in kept memory; the first " << format("%.1f", r.raylabFirstBuildSeconds * 1e3)
        << ")\n";
    if (r.hasEmbree) {
        printEmbreeText(out, r);
    }
    if (!r.memoryAccessMonitors.empty()) {
        out << "note: the kernel's DAMON samples memory accesses here (";
        for (std::size_t i = 0; i < r.memoryAccessMonitors.size(); ++i) {
            out << (i ? ", " : "") << r.memoryAccessMonitors[i];
        }
        out << "): on a virtual machine it slowed some frames up to 3x (PERFORMANCE.md, \"Machine "
               "and conditions\"); compare several runs\n";
    }
    printHeader(out, r);
    if (r.packets) {
        printRow(out, "raylab (packets)", r.raylabPackets);
        if (r.blocks) {
            printRow(out, "raylab (blocks)", r.raylabBlocks);
        }
        if (r.packets16) {
            printRow(out, "raylab (16/64-ray packets)", r.raylabPackets16);
        }
        printRow(out, "raylab (1 ray)", r.raylabSingle);
    } else {
        printRow(out, "raylab (1 ray)", r.raylab);
    }
    if (r.hasEmbree) {
        for (std::size_t c = 0; c < kEmbreeCalls; ++c) {
            printRow(out, kEmbreeCallText[c].label, r.embree[c].figures);
        }
    } else {
        out << "Embree: " << r.embreeAbsent << "\n";
    }
    if (r.workload == Workload::Bounce) {
        out << "the bounce rays alone (" << r.bounceRays << "):\n";
        printRow(out, "raylab (closestHits)", r.bounceRaylab);
        if (r.hasEmbree) {
            for (std::size_t c = 0; c < kEmbreeCalls; ++c) {
                printRow(out, kEmbreeCallText[c].label, r.bounceEmbree[c]);
            }
        }
    }
    if (r.packets) {
        out << "packets / single rays: "
            << format("%.2f", speedup(r.raylabPackets.one, r.raylabSingle.one)) << " (1 thread), "
            << format("%.2f", speedup(r.raylabPackets.all, r.raylabSingle.all)) << " ("
            << threadsText(r) << "); answers differing: " << r.packetMismatches << "\n";
    }
    if (r.blocks) {
        printRatio(out, "blocks / packets", r.raylabBlocks, r.raylabPackets, r);
        out << "answers differing from packets: " << r.blockMismatches
            << "; blocks through frustum candidates: camera " << r.cameraBlocksThroughCandidates
            << " of " << r.cameraBlocks << " ("
            << format("%.1f", percent(r.cameraBlocksThroughCandidates, r.cameraBlocks))
            << "%), shadow " << r.shadowBlocksThroughCandidates << " of " << r.shadowBlocks << " ("
            << format("%.1f", percent(r.shadowBlocksThroughCandidates, r.shadowBlocks)) << "%)\n";
    }
    if (r.packets16) {
        printRatio(out, "16/64-ray packets / packets", r.raylabPackets16, r.raylabPackets, r);
        out << "answers differing from packets: " << r.packet16Mismatches << "\n";
    }
    if (r.passes) {
        out << "renderer passes, M pixel samples/s (1 thread, " << threadsText(r)
            << "): lab integrator " << format("%.2f", r.labPasses.oneThread) << ", "
            << format("%.2f", r.labPasses.allThreads) << "; path integrator "
            << format("%.2f", r.pathPasses.oneThread) << ", "
            << format("%.2f", r.pathPasses.allThreads) << "\n";
        out << "  lab integrator in passes of " << kSamplesPerPass
            << " samples (raylab-render's): " << format("%.2f", r.labPassesOfMany.oneThread) << ", "
            << format("%.2f", r.labPassesOfMany.allThreads) << "\n";
    }
    if (!r.hasEmbree) {
        return;
    }
    const std::string raylab = "raylab (" + r.raylabPath + ")";
    for (std::size_t c = 0; c < kEmbreeCalls; ++c) {
        printRatio(out, (raylab + " / " + kEmbreeCallText[c].label).c_str(), r.raylab,
                   r.embree[c].figures, r);
    }
    out << "Embree's best: " << kEmbreeCallText[bestEmbreeCall(r, true)].call << " (1 thread), "
        << kEmbreeCallText[bestEmbreeCall(r, false)].call << " (" << threadsText(r) << ")\n";
    printRatio(out, (raylab + " / Embree's best").c_str(), r.raylab, bestFigures(r), r);
    if (r.workload == Workload::Bounce) {
        printRatio(out, "bounce rays, raylab closestHits / Embree rtcIntersect1", r.bounceRaylab,
                   r.bounceEmbree[0], r);
    }
    for (std::size_t c = 0; c < kEmbreeCalls; ++c) {
        const EmbreeCallFigures& e = r.embree[c];
        out << "disagreeing with " << kEmbreeCallText[c].label << ": closest hits "
            << e.disagreeingHits << " of " << r.primaryRays << ", shadow rays "
            << e.disagreeingShadows << " of " << r.shadowRays;
        if (r.workload == Workload::Bounce) {
            out << ", bounce hits " << e.disagreeingBounceHits << " of " << r.bounceRays;
        }
        out << "\n";
    }
}

void printJson(std::ostream& out, const BenchReport& r) {
    out << "{\"scene\": " << quoted(r.scene)
        << ", \"workload\": " << quoted(workloadName(r.workload))
        << ", \"triangles\": " << r.triangles << ", \"skipped_triangles\": " << r.skipped
        << ", \"width\": " << r.width << ", \"height\": " << r.height
        << ", \"threads\": " << r.threads << ", \"frames\": " << r.frames
        << ", \"builds\": " << r.builds << ", \"primary_rays\": " << r.primaryRays
        << ", \"shadow_rays\": " << r.shadowRays << ", \"bounce_rays\": " << r.bounceRays
        << ", \"memory_access_monitors\": [";
    for (std::size_t i = 0; i < r.memoryAccessMonitors.size(); ++i) {
        out << (i ? ", " : "") << quoted(r.memoryAccessMonitors[i]);
    }
    out << "],\n \"raylab\": ";
    jsonFiguresOpen(out, r.raylab);
    out << ", \"first_build_ms\": " << format("%.3f", r.raylabFirstBuildSeconds * 1e3) << "}";
    out << ", \"raylab_path\": " << quoted(r.raylabPath)
        << ", \"packets\": " << (r.packets ? "true" : "false");
    if (r.packets) {
        out << ",\n \"raylab_packets\": ";
        jsonFigures(out, r.raylabPackets);
        out << ",\n \"raylab_single_ray\": ";
        jsonFigures(out, r.raylabSingle);
        out << ", \"packet_mismatches\": " << r.packetMismatches;
    }
    out << ", \"blocks\": " << (r.blocks ? "true" : "false");
    if (r.blocks) {
        out << ",\n \"raylab_blocks\": ";
        jsonFigures(out, r.raylabBlocks);
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
    out << ", \"packets16\": " << (r.packets16 ? "true" : "false");
    if (r.packets16) {
        out << ",\n \"raylab_packets16\": ";
        jsonFigures(out, r.raylabPackets16);
        out << ", \"packet16_mismatches\": " << r.packet16Mismatches;
    }
    if (r.passes) {
        const auto passJson = [&out](const PassFigures& f) {
            out << "{\"one_thread\": {\"msamples_per_s\": " << format("%.3f", f.oneThread)
                << "}, \"all_threads\": {\"msamples_per_s\": " << format("%.3f", f.allThreads)
                << "}}";
        };
        out << ",\n \"passes\": {\"lab\": ";
        passJson(r.labPasses);
        out << ", \"lab_passes_of_" << kSamplesPerPass << "\": ";
        passJson(r.labPassesOfMany);
        out << ", \"path\": ";
        passJson(r.pathPasses);
        out << "}";
    }
    out << ",\n \"bvh\": {\"traversal\": " << quoted(r.traversal) << ", \"depth\": " << r.bvhDepth
        << ", \"memory_bytes\": " << r.bvhBytes << ", \"leaf_triangles\": " << r.leafReferences
        << "}";
    if (!r.hasEmbree) {
        out << ",\n \"embree\": null, \"embree_best\": null, \"embree_single\": null,"
               " \"embree_packet16\": null, \"embree_stream\": null";
    } else {
        const TracerFigures best = bestFigures(r);
        // Embree's BVH, and the figures of its best call.
        out << ",\n \"embree\": ";
        jsonFiguresOpen(out, best);
        out << ", \"isa\": " << quoted(r.embreeIsa.empty() ? "default" : r.embreeIsa)
            << ", \"memory_bytes\": " << r.embreeBytes
            << ", \"geometry_bytes\": " << r.embreeGeometryBytes
            << ", \"first_build_ms\": " << format("%.3f", r.embreeFirstBuildSeconds * 1e3) << "}";
        out << ",\n \"embree_best\": ";
        jsonFiguresOpen(out, best);
        out << ", \"call_one_thread\": " << quoted(kEmbreeCallText[bestEmbreeCall(r, true)].call)
            << ", \"call_all_threads\": " << quoted(kEmbreeCallText[bestEmbreeCall(r, false)].call);
        jsonRatios(out, r.raylab, best);
        out << "}";
        std::size_t disagreeingHits = 0, disagreeingShadows = 0, disagreeingBounces = 0;
        for (std::size_t c = 0; c < kEmbreeCalls; ++c) {
            const EmbreeCallFigures& e = r.embree[c];
            out << ",\n \"" << kEmbreeCallText[c].key << "\": ";
            jsonFiguresOpen(out, e.figures);
            out << ", \"call\": " << quoted(kEmbreeCallText[c].call);
            jsonRatios(out, r.raylab, e.figures);
            out << ", \"disagreeing_hits\": " << e.disagreeingHits
                << ", \"disagreeing_shadow_rays\": " << e.disagreeingShadows
                << ", \"disagreeing_bounce_hits\": " << e.disagreeingBounceHits << "}";
            disagreeingHits = std::max(disagreeingHits, e.disagreeingHits);
            disagreeingShadows = std::max(disagreeingShadows, e.disagreeingShadows);
            disagreeingBounces = std::max(disagreeingBounces, e.disagreeingBounceHits);
        }
        // raylab's path over Embree's best call; the most disagreeing answers of any call.
        out << "\n";
        jsonRatios(out, r.raylab, best);
        out << ", \"disagreeing_hits\": " << disagreeingHits
            << ", \"disagreeing_shadow_rays\": " << disagreeingShadows
            << ", \"disagreeing_bounce_hits\": " << disagreeingBounces;
        if (r.blocks) {
            jsonRatios(out, r.raylabBlocks, best, "blocks_");
        }
        if (r.packets16) {
            jsonRatios(out, r.raylabPackets16, best, "packets16_");
        }
    }
    if (r.workload == Workload::Bounce) {
        out << ",\n \"bounce\": {\"rays\": " << r.bounceRays << ", \"raylab\": ";
        jsonFigures(out, r.bounceRaylab);
        if (r.hasEmbree) {
            for (std::size_t c = 0; c < kEmbreeCalls; ++c) {
                out << ", \"" << kEmbreeCallText[c].key << "\": ";
                jsonFiguresOpen(out, r.bounceEmbree[c]);
                out << ", \"call\": " << quoted(kEmbreeCallText[c].call);
                jsonRatios(out, r.bounceRaylab, r.bounceEmbree[c]);
                out << "}";
            }
            // The goal's ratio: raylab's closestHits over Embree's single-ray calls.
            jsonRatios(out, r.bounceRaylab, r.bounceEmbree[0]);
        }
        out << "}";
    } else {
        out << ",\n \"bounce\": null";
    }
    out << "}\n";
}

} // namespace raylab::bench
