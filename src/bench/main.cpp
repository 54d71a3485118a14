// raylab-bench [SCENE] [camera and light options] [--threads N] [--frames N] [--json]
//               [--workload primary|bounce] [--embree-isa NAME]
//
// Traces the lab's workload (one primary ray per pixel, one shadow ray per lit hit, and with
// --workload bounce one diffuse bounce ray per hit; 1280 x 720 unless --width/--height say
// otherwise) with raylab's BVH on 1 thread and on N threads, best of --frames frames, and, where
// Embree is built in, with Embree's single-ray, 16-ray packet and stream calls on the same rays,
// converted to Embree's layouts before timing (embree_rays.h), then compares their answers.
// raylab traces packets of 8 consecutive rays (core/bvh_packet.h) and, in the same turns, 8 x 8
// pixel blocks through frustum candidates as the renderer does (core/bvh_frustum.h,
// bench_blocks.h), the same blocks' rows two by two as packets of 16 rays (AVX-512 where the CPU
// has it, else two of 8, as the renderer traces meshes) and single rays; bounce rays in every case
// as the path integrator traces them (closestHits: interleaved walks on large scenes, else one by
// one). Bench-only flags: BenchOptions in io/command_line.h. Exit codes: 2 usage, 1 other errors,
// too many hits disagreeing with Embree, or packets, blocks, 16-ray packets and single rays not
// giving identical answers.

#include "bench_blocks.h"
#include "bench_checks.h"
#include "bench_rays.h"
#include "bench_report.h"
#include "bench_system.h"
#include "bench_timing.h"
#include "core/bvh/bvh.h"
#include "core/bvh/bvh_packet.h"
#include "core/camera.h"
#include "core/integrators/lab_shading.h"
#include "core/render/parallel_tiles.h"
#include "core/render/renderer.h"
#include "core/scene_framing.h"
#include "io/command_line.h"
#include "io/load_progress.h"
#include "io/mesh_import.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#ifdef RAYLAB_HAVE_EMBREE
#include "embree_rays.h"
#include "embree_scene.h"
#endif

namespace {

using namespace raylab;
using namespace raylab::bench;

// raylab's and Embree's build times are each the best of kMinBuilds builds, or of more (up to
// kMaxBuilds) while all builds so far took less than kBuildSeconds: a build's time has a long
// tail on a shared machine (Sponza's best of 5 was 1.17-1.26 times its best of 20).
constexpr int kMinBuilds = 5;
constexpr int kMaxBuilds = 20;
constexpr double kBuildSeconds = 2.0;

// One tracer's part of a frame: `prepare` (untimed; may be empty), then every tile (timed).
struct Turn {
    const TileTracer* trace;
    std::function<void()> prepare;
    TracerFigures* figures;
};

// Times each turn `frames` times, one frame each in turn, keeping each one's best and mean.
void timeInTurns(const BenchRays& rays, int threads, int frames, const std::vector<Turn>& turns,
                 FrameTimes TracerFigures::*which) {
    for (const Turn& turn : turns) {
        (turn.figures->*which).bestSeconds = 1e30;
        (turn.figures->*which).meanSeconds = 0.0;
    }
    for (int frame = 0; frame < frames; ++frame) {
        for (const Turn& turn : turns) {
            if (turn.prepare) {
                turn.prepare();
            }
            const FrameTimes t = timeFrames(rays, threads, 1, *turn.trace);
            FrameTimes& out = turn.figures->*which;
            out.bestSeconds = std::min(out.bestSeconds, t.bestSeconds);
            out.meanSeconds += t.bestSeconds / frames;
        }
    }
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Exit code 1 with a line on stderr when more than 1 in kMaxDisagreement of `rays` closest hits
// disagree with Embree.
bool tooManyDisagree(std::size_t disagreeing, std::size_t rays, const char* what) {
    if (disagreeing * kMaxDisagreement <= rays) {
        return false;
    }
    std::cerr << "raylab-bench: " << disagreeing << " of " << rays << " " << what
              << " disagree with Embree (more than 1 in " << kMaxDisagreement << ")\n";
    return true;
}

int run(int argc, char** argv) {
    std::string error;
    CommandLine cl;
    const int parsed = parseCommandLine(argc, argv, Program::Bench, cl, error);
    if (parsed != 0) {
        std::cerr << "raylab-bench: " << error << "\n";
        return parsed;
    }
    if (cl.help) {
        std::cout << usage(Program::Bench);
        return 0;
    }
    const BenchOptions& flags = cl.bench;
    const Workload workload = flags.bounceWorkload ? Workload::Bounce : Workload::Primary;

    BenchReport report;
    Scene scene;
    std::string warnings;
    bool loaded = false;
    {
        LoadProgressLine progress("raylab-bench", cl.scene); // erased at the end of this block
        loaded = loadScene(cl.scene, cl.importLimits, scene, warnings, error, progress.control());
    }
    if (!loaded) {
        std::cerr << "raylab-bench: " << error << "\n";
        return 1;
    }
    if (!warnings.empty()) {
        std::cerr << warnings;
    }
    // The scene's camera and light, placed as raylab-render places them.
    if (const std::string why = finishSettings(scene, cl); !why.empty()) {
        std::cerr << "raylab-bench: " << why << "\n";
        return 1;
    }
    const int threads = resolveThreadCount(cl.settings.threads);
    const int frames = std::max(1, cl.benchFrames);
    report.scene = cl.scene;
    report.workload = workload;
    report.triangles = scene.triangles.size();
    report.width = cl.settings.width;
    report.height = cl.settings.height;
    report.threads = threads;
    report.memoryAccessMonitors = memoryAccessMonitors();
    report.frames = frames;

    // The BVHs: raylab's and Embree's builds in turns, each timed from the release of the
    // previous one; each side's time the best of its builds (kMinBuilds, above), and its first.
#ifdef RAYLAB_HAVE_EMBREE
    std::unique_ptr<EmbreeScene> embree;
    if (flags.noEmbree) {
        report.embreeAbsent = "skipped (--no-embree)";
    } else {
        EmbreeOptions options;
        options.isa = flags.embreeIsa;
        options.threads = threads;
        embree = std::make_unique<EmbreeScene>(scene, options);
    }
#endif
    BvhBuildOptions buildOptions;
    buildOptions.threads = threads;
    buildOptions.simd = !flags.scalar;
    if (flags.spatialBudget >= 0.0f) {
        buildOptions.spatialSplitBudget = flags.spatialBudget;
    }
    if (flags.presplitBudget >= 0.0f) {
        buildOptions.presplitBudget = flags.presplitBudget;
    }
    if (flags.spatialMinGain >= 0.0f) {
        buildOptions.spatialSplitMinGain = flags.spatialMinGain;
    }
    // raylab's builds after the second work in the memory the one before kept, as a program
    // rebuilding its scene would (BvhBuildMemory); Embree's reuse what glibc's heap kept of theirs
    // (mallopt, in main). The first build's memory is let go before Embree's first build, so that
    // each side's first build finds the other's working memory returned to the system: in the
    // Zen 5 guest, with raylab's kept, Embree's first dragon build took 304-338 ms against
    // 201-211 (three runs each).
    Bvh bvh;
    BvhBuildMemory buildMemory;
    double raylabBuildSeconds = 1e30;
    const auto buildsStart = std::chrono::steady_clock::now();
    for (int i = 0; i < kMinBuilds || (i < kMaxBuilds && secondsSince(buildsStart) < kBuildSeconds);
         ++i) {
        const auto start = std::chrono::steady_clock::now();
        rebuildBvh(scene, buildOptions, buildMemory, bvh);
        const double seconds = secondsSince(start);
        raylabBuildSeconds = std::min(raylabBuildSeconds, seconds);
        if (i == 0) {
            report.raylabFirstBuildSeconds = seconds;
            buildMemory = BvhBuildMemory();
        }
        report.builds = i + 1;
#ifdef RAYLAB_HAVE_EMBREE
        if (embree && embree->ok()) {
            embree->build();
        }
#endif
    }
    buildMemory = BvhBuildMemory(); // not needed while tracing
#ifdef RAYLAB_HAVE_EMBREE
    if (embree && !embree->ok()) {
        std::cerr << "raylab-bench: " << embree->error() << "\n";
        return 1;
    }
#endif
    report.skipped = bvh.skippedTriangles;
    report.bvhBytes = bvh.memoryBytes();
    report.bvhDepth = bvh.depth();
    report.leafReferences = bvh.leafReferences;
    report.traversal = bvh.wideNodes.empty() ? "scalar binary" : "8-wide AVX2";

    // The workload: primary rays, raylab's hits (untimed), then their shadow and bounce rays.
    BenchRays rays = makePrimaryRays(cl.settings);
    std::vector<Hit> hits(rays.primary.size());
    auto closest = [&](const Ray& ray) {
        return flags.scalar ? closestHitScalar(bvh, ray) : closestHit(bvh, ray);
    };
    auto any = [&](const Ray& ray) {
        return flags.scalar ? anyHitScalar(bvh, ray) : anyHit(bvh, ray);
    };
    const TileTracer primaryOnly = [&](std::size_t tile) {
        for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
            hits[i] = closest(rays.primary[i]);
        }
    };
    timeFrames(rays, threads, 1, primaryOnly);
    addShadowRays(rays, hits, scene, cl.settings);
    if (workload == Workload::Bounce) {
        addBounceRays(rays, hits, scene, cl.settings.shadowEpsilon);
    }
    std::vector<uint8_t> occluded(rays.shadow.size(), 0);
    std::vector<Hit> bounceHits(rays.bounce.size());
    report.primaryRays = rays.primary.size();
    report.shadowRays = rays.shadow.size();
    report.bounceRays = rays.bounce.size();

    // Bounce rays as the path integrator traces them, through closestHits (interleaved walks on
    // large scenes, else one by one), in every raylab tracer; one by one with --scalar.
    auto traceBounces = [&](std::size_t tile) {
        const std::size_t first = rays.bounceOffset[tile], last = rays.bounceOffset[tile + 1];
        if (!flags.scalar) {
            closestHits(bvh, &rays.bounce[first], last - first, &bounceHits[first]);
            return;
        }
        for (std::size_t j = first; j < last; ++j) {
            bounceHits[j] = closest(rays.bounce[j]);
        }
    };
    const TileTracer bounceTile = traceBounces;
    // Single rays, one by one.
    const TileTracer singleTile = [&](std::size_t tile) {
        for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
            hits[i] = closest(rays.primary[i]);
        }
        for (std::size_t j = rays.shadowOffset[tile]; j < rays.shadowOffset[tile + 1]; ++j) {
            occluded[j] = any(rays.shadow[j]) ? 1 : 0;
        }
        traceBounces(tile);
    };
    // Packets of 8 consecutive rays of a tile: 8 pixels of a row, or 8 shadow rays of
    // neighbouring hits, packed (structure of arrays, ray_packet.h) before any timing.
    const bool packets = !flags.scalar && !flags.noPackets;
    report.packets = packets;
    const PacketedRays packeted = packets ? packRays(rays) : PacketedRays{};
    std::vector<HitPacket> packetHits(packeted.primary.size());
    std::vector<unsigned> packetOccluded(packeted.shadow.size(), 0);
    const TileTracer packetTile = [&](std::size_t tile) {
        for (std::size_t i = packeted.primaryOffset[tile]; i < packeted.primaryOffset[tile + 1];
             ++i) {
            closestHit8(bvh, packeted.primary[i], packetHits[i]);
        }
        for (std::size_t j = packeted.shadowOffset[tile]; j < packeted.shadowOffset[tile + 1];
             ++j) {
            packetOccluded[j] = anyHit8(bvh, packeted.shadow[j]);
        }
        traceBounces(tile);
    };
    // 8 x 8 pixel blocks of the same rays, each row a packet, shadow rays in their pixel's lane,
    // traced as the renderer does (bench_blocks.h); packed, and their answers sized, before any
    // timing.
    const bool blocks = packets && !flags.noBlocks;
    report.blocks = blocks;
    const BlockedRays blocked = blocks ? blockRays(rays) : BlockedRays{};
    // The same blocks as packets of 16 rays (bench_blocks.h), full blocks in 4 x 4 tiles, as the
    // renderer traces a scene it does not trace in blocks.
    const bool packets16 = blocks;
    report.packets16 = packets16;
    const BlockedRays tiled = packets16 ? blockRays(rays, BlockLayout::Tiles4x4) : BlockedRays{};
    const PrimaryRays camera(cl.settings.camera, cl.settings.width, cl.settings.height);
    BlockAnswers pairAnswers = makeBlockAnswers(tiled);
    const TileTracer pairTile = [&](std::size_t tile) {
        TileCarry carry; // as the renderer's tile loop (lab_pass.cpp)
        for (std::size_t b = tiled.blockOffset[tile]; b < tiled.blockOffset[tile + 1]; ++b) {
            traceBlockInPacketPairs(bvh, camera, tiled, b, pairAnswers, carry);
        }
        traceBounces(tile);
    };
    BlockAnswers blockAnswers = makeBlockAnswers(blocked);
    const glm::vec3 light = cl.settings.light.position;
    const bool shadowFrustum = cl.settings.shadowEpsilon >= 0.0f; // as shadeLabBlock
    const TileTracer blockTile = [&](std::size_t tile) {
        for (std::size_t b = blocked.blockOffset[tile]; b < blocked.blockOffset[tile + 1]; ++b) {
            traceBlock(bvh, camera, blocked, b, light, shadowFrustum, blockAnswers);
        }
        traceBounces(tile);
    };

    // Every tracer takes its turn frame by frame, so all see the same load on a shared machine.
    // `turns` trace the whole workload; `bounceTurns` its bounce rays alone.
    std::vector<Turn> turns;
    std::vector<Turn> bounceTurns;
    for (TracerFigures* f : {&report.raylabPackets, &report.raylabBlocks, &report.raylabPackets16,
                             &report.raylabSingle}) {
        f->rays = rays.total();
        f->buildSeconds = raylabBuildSeconds;
    }
    if (packets) {
        turns.push_back({&packetTile, {}, &report.raylabPackets});
    }
    if (blocks) {
        turns.push_back({&blockTile, {}, &report.raylabBlocks});
    }
    if (packets16) {
        turns.push_back({&pairTile, {}, &report.raylabPackets16});
    }
    turns.push_back({&singleTile, {}, &report.raylabSingle});
    report.bounceRaylab.rays = rays.bounce.size();
    report.bounceRaylab.buildSeconds = raylabBuildSeconds;
    bounceTurns.push_back({&bounceTile, {}, &report.bounceRaylab});
#ifdef RAYLAB_HAVE_EMBREE
    std::array<std::unique_ptr<EmbreeRays>, kEmbreeCalls> embreeRays;
    std::array<TileTracer, kEmbreeCalls> embreeTile, embreeBounceTile;
    if (embree) {
        report.hasEmbree = true;
        report.embreeIsa = flags.embreeIsa;
        report.embreeBuildSeconds = embree->buildSeconds();
        report.embreeFirstBuildSeconds = embree->firstBuildSeconds();
        report.embreeBytes = embree->memoryBytes();
        report.embreeGeometryBytes = embree->geometryBytes();
        for (std::size_t c = 0; c < kEmbreeCalls; ++c) {
            EmbreeRays* layout =
                (embreeRays[c] = makeEmbreeRays(static_cast<EmbreeCall>(c), *embree, rays)).get();
            embreeTile[c] = [layout](std::size_t tile) { layout->traceTile(tile, kAllSets); };
            embreeBounceTile[c] = [layout](std::size_t tile) {
                layout->traceTile(tile, kBounceSet);
            };
            TracerFigures& f = report.embree[c].figures;
            f.rays = rays.total();
            f.buildSeconds = embree->buildSeconds();
            turns.push_back({&embreeTile[c], [layout] { layout->reset(kAllSets); }, &f});
            report.bounceEmbree[c].rays = rays.bounce.size();
            report.bounceEmbree[c].buildSeconds = embree->buildSeconds();
            bounceTurns.push_back({&embreeBounceTile[c], [layout] { layout->reset(kBounceSet); },
                                   &report.bounceEmbree[c]});
        }
    }
#endif
    timeInTurns(rays, 1, frames, turns, &TracerFigures::one);
    timeInTurns(rays, threads, frames, turns, &TracerFigures::all);
    if (workload == Workload::Bounce) {
        timeInTurns(rays, 1, frames, bounceTurns, &TracerFigures::one);
        timeInTurns(rays, threads, frames, bounceTurns, &TracerFigures::all);
    }
    // The renderer's own path for this scene.
    const bool rendererBlocks = blocks && tracingFor(bvh) == BlockTracing::Frustums;
    report.raylabPath = rendererBlocks ? "blocks"
                        : packets16    ? "packets16"
                        : packets      ? "packets"
                                       : "single rays";
    report.raylab = rendererBlocks ? report.raylabBlocks
                    : packets16    ? report.raylabPackets16
                    : packets      ? report.raylabPackets
                                   : report.raylabSingle;

#ifdef RAYLAB_HAVE_EMBREE
    for (std::size_t c = 0; c < kEmbreeCalls && embree; ++c) {
        const EmbreeAnswers answers = embreeRays[c]->answers();
        EmbreeCallFigures& e = report.embree[c];
        e.disagreeingHits = countDisagreeingHits(hits, answers.primary);
        e.disagreeingBounceHits = countDisagreeingHits(bounceHits, answers.bounce);
        for (std::size_t j = 0; j < occluded.size(); ++j) {
            e.disagreeingShadows += occluded[j] != answers.occluded[j] ? 1 : 0;
        }
    }
#endif
    if (packets &&
        !checkPacketsAndBlocks(
            rays, packeted, RaylabAnswers{hits, occluded, packetHits, packetOccluded},
            blocks ? &blocked : nullptr, blocks ? &blockAnswers : nullptr,
            packets16 ? &tiled : nullptr, packets16 ? &pairAnswers : nullptr, report, error)) {
        std::cerr << "raylab-bench: " << error << "\n";
        return 1;
    }

    if (!flags.noPasses) {
        // The renderer's passes, as raylab-render and the viewer make them.
        RenderSettings lab = cl.settings;
        lab.integrator = Integrator::Lab;
        report.labPasses = measurePasses(scene, bvh, lab, threads, frames);
        report.labPassesOfMany =
            measurePasses(scene, bvh, lab, threads, frames, static_cast<uint32_t>(kSamplesPerPass));
        RenderSettings path = cl.settings;
        path.integrator = Integrator::Path;
        report.pathPasses = measurePasses(scene, bvh, path, threads, frames);
        report.passes = true;
    }
    if (cl.json) {
        printJson(std::cout, report);
    } else {
        printText(std::cout, report);
    }
    for (std::size_t c = 0; c < kEmbreeCalls && report.hasEmbree; ++c) {
        if (tooManyDisagree(report.embree[c].disagreeingHits, report.primaryRays,
                            "closest hits of camera rays") ||
            tooManyDisagree(report.embree[c].disagreeingBounceHits, report.bounceRays,
                            "closest hits of bounce rays")) {
            return 1;
        }
    }
    if (report.packetMismatches != 0) {
        std::cerr << "raylab-bench: " << report.packetMismatches
                  << " packet answers differ from the single-ray ones\n";
        return 1;
    }
    if (report.packet16Mismatches != 0) {
        std::cerr << "raylab-bench: " << report.packet16Mismatches
                  << " 16-ray packet answers differ from the packet ones\n";
        return 1;
    }
    if (report.blockMismatches != 0) {
        std::cerr << "raylab-bench: " << report.blockMismatches
                  << " block answers differ from the packet ones\n";
        return 1;
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
#ifdef __GLIBC__
    // Memory freed to the heap stays in the process (glibc otherwise unmaps large blocks and trims
    // the heap, by thresholds that move with what was freed), so that each of Embree's builds
    // after the first reuses its predecessors' memory, as raylab's reuse theirs (rebuildBvh),
    // whatever the other side's builds did between: without it, Embree's later builds of the thin
    // triangles on 1 thread took 1,265 page faults each and twice as long, in turns with
    // raylab's rebuilds, and 0 on their own (PERFORMANCE.md, "Memory and page faults").
    mallopt(M_MMAP_THRESHOLD, 1 << 30); // blocks of up to 1 GiB from the heap
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "raylab-bench: " << e.what() << "\n";
        return 1;
    }
}
