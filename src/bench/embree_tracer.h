#pragma once
// Intel Embree 3 on the same triangles and the same rays, with its single-ray calls
// (rtcIntersect1 for primary rays, rtcOccluded1 for shadow rays). Built only when CMake finds
// Embree (RAYLAB_WITH_EMBREE); raylab-bench compiles it under RAYLAB_HAVE_EMBREE.

#include "bench_rays.h"
#include "core/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace raylab::bench {

class EmbreeTracer {
public:
    // Builds Embree's BVH over the scene's valid triangles (as buildBvh skips the invalid ones).
    // On failure, ok() is false and error() says why.
    explicit EmbreeTracer(const Scene& scene);
    ~EmbreeTracer();
    EmbreeTracer(const EmbreeTracer&) = delete;
    EmbreeTracer& operator=(const EmbreeTracer&) = delete;

    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }
    double buildSeconds() const { return buildSeconds_; }

    // Traces tile `tile`: closest hits into hits[i] (Hit::triangle the scene index, u and v
    // as Embree reports them) for its primary rays, occlusion into occluded[j] for its shadow rays.
    void traceTile(const BenchRays& rays, std::size_t tile, std::vector<Hit>& hits,
                   std::vector<uint8_t>& occluded) const;

private:
    void* device_ = nullptr;           // RTCDevice
    void* scene_ = nullptr;            // RTCScene
    std::vector<uint32_t> sceneIndex_; // Embree primitive id -> scene triangle index
    std::string error_;
    double buildSeconds_ = 0.0;
};

} // namespace raylab::bench
