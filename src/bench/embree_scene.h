#pragma once
// Intel Embree 3's BVH over a scene's triangles: its device (optionally held to one instruction
// set), its build time and the memory it holds, measured with the device's memory monitor.
// Built only when CMake finds Embree (RAYLAB_WITH_EMBREE); raylab-bench compiles it under
// RAYLAB_HAVE_EMBREE.

#include "core/scene.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <embree3/rtcore.h>
#include <string>
#include <vector>

namespace raylab::bench {

struct EmbreeOptions {
    std::string isa; // empty: Embree's own choice (its widest kernels); else one isEmbreeIsa
                     // (io/command_line.h, isEmbreeIsa) accepts
    int threads = 1; // Embree's build threads ("threads=" configuration), as raylab's build
};

// Sets flush-to-zero and denormals-are-zero on the calling thread, as Embree's documentation asks
// of every thread that calls it, and restores the thread's previous MXCSR when it goes out of
// scope (raylab's tracing runs on the same threads, in IEEE mode).
class FlushDenormals {
public:
    FlushDenormals();
    ~FlushDenormals();
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;

private:
    unsigned saved_;
};

class EmbreeScene {
public:
    // Embree's device and its geometry over the scene's valid triangles, as buildBvh skips the
    // invalid ones; build() makes the BVH. On failure, ok() is false and error() says why.
    EmbreeScene(const Scene& scene, const EmbreeOptions& options);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }
    RTCScene handle() const { return scene_; }
    // The scene's index of Embree primitive primID.
    uint32_t sceneIndex(unsigned primID) const { return sceneIndex_[primID]; }

    // Builds Embree's BVH (its default, medium quality) into handle(), releasing the previous
    // one: a new scene over the geometry (whose buffers were filled and committed once, untimed),
    // committed. Timed from the release; false, with error() set, on failure.
    bool build();
    // Seconds of the fastest build() so far, and of the first (the one a program that builds
    // once waits for: its memory new to the process).
    double buildSeconds() const { return buildSeconds_; }
    double firstBuildSeconds() const { return firstBuildSeconds_; }
    // Bytes the device gained in the last build() and kept: the BVH with its triangle data.
    std::size_t memoryBytes() const { return memoryBytes_; }
    // Bytes of the vertex and index buffers Embree holds besides (3 vertices per triangle).
    std::size_t geometryBytes() const { return geometryBytes_; }

private:
    bool makeGeometry(const Scene& scene); // geometry_ over the valid triangles; false on failure

    RTCDevice device_ = nullptr;
    RTCGeometry geometry_ = nullptr; // shared by every build's scene; null without triangles
    RTCScene scene_ = nullptr;
    std::vector<uint32_t> sceneIndex_;         // Embree primitive id -> scene triangle index
    std::atomic<std::int64_t> deviceBytes_{0}; // the memory monitor's running sum
    std::string error_;
    double buildSeconds_ = 1e30;
    double firstBuildSeconds_ = 0.0;
    std::size_t memoryBytes_ = 0, geometryBytes_ = 0;
};

} // namespace raylab::bench
