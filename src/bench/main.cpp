// raylab-bench [SCENE] [camera and light options] [--threads N] [--frames N] [--json]
//
// Traces the lab's workload (one primary ray per pixel, one shadow ray per lit hit; 1280 x 720
// unless --width/--height say otherwise) with raylab's BVH on 1 thread and on N threads, best of
// --frames frames, and, where Embree is built in, with Embree on the same rays, then compares
// the two's closest hits. raylab traces packets of 8 consecutive rays (core/bvh_packet.h) and,
// in the same turns, 8 x 8 pixel blocks through frustum candidates as the renderer does
// (core/bvh_frustum.h, bench_blocks.h) and single rays. Bench-only flags: --scalar (raylab's
// scalar reference traversal instead of the SIMD one), --no-packets (single rays only),
// --no-blocks, --no-embree. Exit codes: 2 usage, 1 other errors, too many hits disagreeing with
// Embree, or packets, blocks and single rays not giving identical answers.

#include "bench_blocks.h"
#include "bench_rays.h"
#include "bench_report.h"
#include "bench_timing.h"
#include "core/bvh/bvh.h"
#include "core/bvh/bvh_packet.h"
#include "core/camera.h"
#include "core/render/parallel_tiles.h"
#include "core/scene_framing.h"
#include "io/command_line.h"
#include "io/mesh_loader.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#ifdef RAYLAB_HAVE_EMBREE
#include "embree_tracer.h"
#endif

namespace {

using namespace raylab;
using namespace raylab::bench;

constexpr int kBenchWidth = 1280;
constexpr int kBenchHeight = 720;

struct BenchFlags {
    bool scalar = false;
    bool noEmbree = false;
    bool noPackets = false;
    bool noBlocks = false;
    float spatialBudget = -1.0f;  // < 0: BvhBuildOptions' default
    float presplitBudget = -1.0f; // likewise
    bool sizeGiven = false;
};

// Removes the bench-only flags from args and notes whether the image size was given.
BenchFlags takeBenchFlags(std::vector<const char*>& args) {
    BenchFlags flags;
    std::vector<const char*> kept;
    for (const char* arg : args) {
        if (std::strcmp(arg, "--scalar") == 0) {
            flags.scalar = true;
        } else if (std::strcmp(arg, "--no-embree") == 0) {
            flags.noEmbree = true;
        } else if (std::strcmp(arg, "--no-packets") == 0) {
            flags.noPackets = true;
        } else if (std::strcmp(arg, "--no-blocks") == 0) {
            flags.noBlocks = true;
        } else if (std::strncmp(arg, "--spatial-budget=", 17) == 0) {
            flags.spatialBudget = std::stof(arg + 17);
        } else if (std::strncmp(arg, "--presplit-budget=", 18) == 0) {
            flags.presplitBudget = std::stof(arg + 18);
        } else {
            const std::string a = arg;
            if (a.rfind("--width", 0) == 0 || a.rfind("--height", 0) == 0) {
                flags.sizeGiven = true;
            }
            kept.push_back(arg);
        }
    }
    args = kept;
    return flags;
}

// Camera, light and epsilon of a scene: given ones kept, the rest framed as raylab-render does.
void frameMissing(const Scene& scene, CommandLine& cl) {
    RenderSettings framed = cl.settings;
    if (cl.scene != "cornell") {
        frameScene(scene, framed);
    }
    if (!cl.cameraGiven) {
        cl.settings.camera = framed.camera;
    }
    if (!cl.lightGiven) {
        cl.settings.light = framed.light;
    }
    if (!cl.shadowEpsilonGiven) {
        cl.settings.shadowEpsilon = framed.shadowEpsilon;
    }
    if (cl.lookAt) {
        lookAt(cl.settings.camera, *cl.lookAt);
    }
}

// Times each tracer `frames` times, one frame each in turn, keeping each one's best and mean.
void timeInTurns(const BenchRays& rays, int threads, int frames,
                 const std::vector<const TileTracer*>& tracers,
                 const std::vector<TracerFigures*>& figures, FrameTimes TracerFigures::*which) {
    for (TracerFigures* f : figures) {
        (f->*which).bestSeconds = 1e30;
        (f->*which).meanSeconds = 0.0;
    }
    for (int frame = 0; frame < frames; ++frame) {
        for (std::size_t i = 0; i < tracers.size(); ++i) {
            const FrameTimes t = timeFrames(rays, threads, 1, *tracers[i]);
            FrameTimes& out = figures[i]->*which;
            out.bestSeconds = std::min(out.bestSeconds, t.bestSeconds);
            out.meanSeconds += t.bestSeconds / frames;
        }
    }
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int run(int argc, char** argv) {
    std::vector<const char*> args(argv, argv + argc);
    const BenchFlags flags = takeBenchFlags(args);
    CommandLine cl;
    std::string error;
    if (!flags.sizeGiven) {
        cl.settings.width = kBenchWidth;
        cl.settings.height = kBenchHeight;
    }
    const int parsed =
        parseCommandLine(static_cast<int>(args.size()), args.data(), Program::Bench, cl, error);
    if (parsed != 0) {
        std::cerr << "raylab-bench: " << error << "\n";
        return parsed;
    }
    if (cl.help) {
        std::cout << usage(Program::Bench)
                  << "\nraylab-bench traces 1280x720 unless --width or --height is given.\n"
                     "  --scalar                raylab's scalar reference traversal (binary BVH)\n"
                     "  --no-packets            single rays only (no 8-ray packets, no blocks)\n"
                     "  --no-blocks             no 8x8 pixel blocks through frustum candidates\n"
                     "  --spatial-budget=F      BVH spatial splits: extra references, fraction\n"
                     "  --presplit-budget=F     BVH pre-splitting: extra references, fraction\n"
                     "  --no-embree             skip Embree\n";
        return 0;
    }
    if (!flags.sizeGiven) {
        cl.settings.width = kBenchWidth;
        cl.settings.height = kBenchHeight;
    }

    BenchReport report;
    Scene scene;
    MeshLoadReport loadReport;
    if (!loadScene(cl.scene, scene, loadReport, error)) {
        std::cerr << "raylab-bench: " << error << "\n";
        return 1;
    }
    if (const std::string warnings = describe(loadReport, cl.scene); !warnings.empty()) {
        std::cerr << warnings << (warnings.back() == '\n' ? "" : "\n");
    }
    frameMissing(scene, cl);
    const int threads = resolveThreadCount(cl.settings.threads);
    const int frames = std::max(1, cl.benchFrames);
    report.scene = cl.scene;
    report.triangles = scene.triangles.size();
    report.width = cl.settings.width;
    report.height = cl.settings.height;
    report.threads = threads;
    report.frames = frames;

    // raylab's BVH: best of three builds.
    BvhBuildOptions buildOptions;
    buildOptions.threads = threads;
    buildOptions.simd = !flags.scalar;
    if (flags.spatialBudget >= 0.0f) {
        buildOptions.spatialSplitBudget = flags.spatialBudget;
    }
    if (flags.presplitBudget >= 0.0f) {
        buildOptions.presplitBudget = flags.presplitBudget;
    }
    Bvh bvh;
    report.raylab.buildSeconds = 1e30;
    for (int i = 0; i < 3; ++i) {
        const auto start = std::chrono::steady_clock::now();
        bvh = buildBvh(scene, buildOptions);
        report.raylab.buildSeconds = std::min(report.raylab.buildSeconds, secondsSince(start));
    }
    report.skipped = bvh.skippedTriangles;
    report.bvhBytes = bvh.memoryBytes();
    report.bvhDepth = bvh.depth();
    report.leafReferences = bvh.leafReferences;
    report.traversal = bvh.wideNodes.empty() ? "scalar binary" : "8-wide AVX2";

    // The workload: primary rays, raylab's hits (untimed), then their shadow rays.
    BenchRays rays = makePrimaryRays(cl.settings);
    std::vector<Hit> hits(rays.primary.size());
    std::vector<uint8_t> occluded;
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
    occluded.assign(rays.shadow.size(), 0);
    report.primaryRays = rays.primary.size();
    report.shadowRays = rays.shadow.size();

    // Single rays, one by one.
    const TileTracer singleTile = [&](std::size_t tile) {
        for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
            hits[i] = closest(rays.primary[i]);
        }
        for (std::size_t j = rays.shadowOffset[tile]; j < rays.shadowOffset[tile + 1]; ++j) {
            occluded[j] = any(rays.shadow[j]) ? 1 : 0;
        }
    };
    // Packets of 8 consecutive rays of a tile: 8 pixels of a row, or 8 shadow rays of
    // neighbouring hits, packed (structure of arrays, ray_packet.h) before any timing.
    const PacketedRays packeted = packRays(rays);
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
    };
    const bool packets = !flags.scalar && !flags.noPackets;
    report.packets = packets;
    // 8 x 8 pixel blocks of the same rays, each row a packet, shadow rays in their pixel's lane,
    // traced as the renderer does (bench_blocks.h); packed, and their answers sized, before any
    // timing.
    const bool blocks = packets && !flags.noBlocks;
    report.blocks = blocks;
    const BlockedRays blocked = blocks ? blockRays(rays) : BlockedRays{};
    BlockAnswers blockAnswers = makeBlockAnswers(blocked);
    const glm::vec3 light = cl.settings.light.position;
    const bool shadowFrustum = cl.settings.shadowEpsilon >= 0.0f; // as shadeLabBlock
    const PrimaryRays camera(cl.settings.camera, cl.settings.width, cl.settings.height);
    const TileTracer blockTile = [&](std::size_t tile) {
        for (std::size_t b = blocked.blockOffset[tile]; b < blocked.blockOffset[tile + 1]; ++b) {
            traceBlock(bvh, camera, blocked, b, light, shadowFrustum, blockAnswers);
        }
    };
    // raylab and Embree take turns frame by frame, so both see the same load on a shared machine.
    std::vector<const TileTracer*> tracers{packets ? &packetTile : &singleTile};
    std::vector<TracerFigures*> figures{&report.raylab};
    if (blocks) {
        tracers.push_back(&blockTile);
        figures.push_back(&report.raylabBlocks);
    }
    if (packets) {
        tracers.push_back(&singleTile);
        figures.push_back(&report.raylabSingle);
    }
#ifdef RAYLAB_HAVE_EMBREE
    std::unique_ptr<EmbreeTracer> embree;
    std::vector<Hit> embreeHits;
    std::vector<uint8_t> embreeOccluded;
    const TileTracer embreeTile = [&](std::size_t tile) {
        embree->traceTile(rays, tile, embreeHits, embreeOccluded);
    };
    if (flags.noEmbree) {
        report.embreeAbsent = "skipped (--no-embree)";
    } else {
        embree = std::make_unique<EmbreeTracer>(scene);
        if (!embree->ok()) {
            std::cerr << "raylab-bench: " << embree->error() << "\n";
            return 1;
        }
        embreeHits.resize(rays.primary.size());
        embreeOccluded.assign(rays.shadow.size(), 0);
        report.hasEmbree = true;
        report.embree.buildSeconds = embree->buildSeconds();
        tracers.push_back(&embreeTile);
        figures.push_back(&report.embree);
    }
#endif
    timeInTurns(rays, 1, frames, tracers, figures, &TracerFigures::one);
    timeInTurns(rays, threads, frames, tracers, figures, &TracerFigures::all);
#ifdef RAYLAB_HAVE_EMBREE
    if (embree) {
        report.disagreeingHits = countDisagreeingHits(hits, embreeHits);
        for (std::size_t j = 0; j < occluded.size(); ++j) {
            report.disagreeingShadows += occluded[j] != embreeOccluded[j] ? 1 : 0;
        }
    }
#endif

    if (packets) {
        // The packets' answer for each ray: ray k of a tile is lane k % 8 of the tile's packet
        // k / 8 (bench_rays.h).
        std::vector<Hit> packetHit(rays.primary.size());
        std::vector<uint8_t> packetAnswer(rays.shadow.size());
        for (std::size_t tile = 0; tile < rays.tiles(); ++tile) {
            for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
                const std::size_t k = i - rays.primaryOffset[tile];
                packetHit[i] = packetHits[packeted.primaryOffset[tile] + k / kPacketSize].hit(
                    static_cast<int>(k % kPacketSize));
                report.packetMismatches +=
                    std::memcmp(&hits[i], &packetHit[i], sizeof(Hit)) != 0 ? 1 : 0;
            }
            for (std::size_t j = rays.shadowOffset[tile]; j < rays.shadowOffset[tile + 1]; ++j) {
                const std::size_t k = j - rays.shadowOffset[tile];
                const unsigned answers =
                    packetOccluded[packeted.shadowOffset[tile] + k / kPacketSize];
                packetAnswer[j] = ((answers >> (k % kPacketSize)) & 1u) != 0 ? 1 : 0;
                report.packetMismatches += (occluded[j] != 0) != (packetAnswer[j] != 0) ? 1 : 0;
            }
        }
        if (blocks) {
            // Every lane of every block against the packets' answer for the same ray, bit for bit.
            std::size_t cameraSeen = 0, shadowSeen = 0;
            for (std::size_t p = 0; p < blocked.primary.size(); ++p) {
                for (int lane = 0; lane < kPacketSize; ++lane) {
                    const std::size_t slot = p * kPacketSize + static_cast<std::size_t>(lane);
                    if (const uint32_t i = blocked.primaryRay[slot]; i != kNoRay) {
                        const Hit blockHit = blockAnswers.hits[p].hit(lane);
                        report.blockMismatches +=
                            std::memcmp(&blockHit, &packetHit[i], sizeof(Hit)) != 0 ? 1 : 0;
                        ++cameraSeen;
                    }
                    if (const uint32_t j = blocked.shadowRay[slot]; j != kNoRay) {
                        const bool blockAnswer = ((blockAnswers.occluded[p] >> lane) & 1u) != 0;
                        report.blockMismatches += blockAnswer != (packetAnswer[j] != 0) ? 1 : 0;
                        ++shadowSeen;
                    }
                }
            }
            if (cameraSeen != rays.primary.size() || shadowSeen != rays.shadow.size()) {
                std::cerr << "raylab-bench: the blocks hold " << cameraSeen << " camera and "
                          << shadowSeen << " shadow rays, not " << rays.primary.size() << " and "
                          << rays.shadow.size() << "\n";
                return 1;
            }
            report.cameraBlocks = blocked.blocks();
            for (std::size_t b = 0; b < blocked.blocks(); ++b) {
                const uint8_t f = blockAnswers.flags[b];
                report.cameraBlocksThroughCandidates += (f & kCameraCandidates) != 0 ? 1 : 0;
                report.shadowBlocks += blocked.blockShadowRays[b];
                report.shadowBlocksThroughCandidates += (f & kShadowCandidates) != 0 ? 1 : 0;
            }
        }
    }

    if (cl.json) {
        printJson(std::cout, report);
    } else {
        printText(std::cout, report);
    }
    if (report.hasEmbree && report.disagreeingHits * kMaxDisagreement > report.primaryRays) {
        std::cerr << "raylab-bench: " << report.disagreeingHits << " of " << report.primaryRays
                  << " closest hits disagree with Embree (more than 1 in " << kMaxDisagreement
                  << ")\n";
        return 1;
    }
    if (report.packetMismatches != 0) {
        std::cerr << "raylab-bench: " << report.packetMismatches
                  << " packet answers differ from the single-ray ones\n";
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
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::cerr << "raylab-bench: " << e.what() << "\n";
        return 1;
    }
}
