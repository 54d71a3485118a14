#include "embree_scene.h"

#include <algorithm>
#include <chrono>
#include <pmmintrin.h>
#include <sys/types.h>
#include <xmmintrin.h>

namespace raylab::bench {

namespace {

// The device's memory monitor: bytes > 0 before an allocation, < 0 after a release. Called from
// Embree's build threads, hence the atomic sum. Never refuses an allocation.
bool countBytes(void* sum, ssize_t bytes, bool /*post*/) {
    static_cast<std::atomic<std::int64_t>*>(sum)->fetch_add(static_cast<std::int64_t>(bytes));
    return true;
}

std::size_t grownBy(std::int64_t before, std::int64_t after) {
    return after > before ? static_cast<std::size_t>(after - before) : 0;
}

} // namespace

FlushDenormals::FlushDenormals() : saved_(_mm_getcsr()) {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
}

FlushDenormals::~FlushDenormals() { _mm_setcsr(saved_); }

EmbreeScene::EmbreeScene(const Scene& scene, const EmbreeOptions& options) {
    std::string config = "threads=" + std::to_string(std::max(1, options.threads));
    if (!options.isa.empty()) {
        config += ",isa=" + options.isa;
    }
    device_ = rtcNewDevice(config.c_str());
    if (!device_) {
        error_ = "Embree: cannot create a device (" + config + ")";
        return;
    }
    rtcSetDeviceMemoryMonitorFunction(device_, countBytes, &deviceBytes_);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        if (isValidTriangle(scene.triangles[i])) {
            sceneIndex_.push_back(static_cast<uint32_t>(i));
        }
    }
    const std::int64_t before = deviceBytes_.load();
    if (!makeGeometry(scene)) {
        return;
    }
    geometryBytes_ = grownBy(before, deviceBytes_.load());
}

bool EmbreeScene::makeGeometry(const Scene& scene) {
    if (sceneIndex_.empty()) {
        return true;
    }
    geometry_ = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t count = sceneIndex_.size();
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry_, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
    if (!vertices || !indices) {
        error_ = "Embree: cannot allocate the geometry buffers";
        return false;
    }
    for (std::size_t i = 0; i < count; ++i) {
        const Triangle& t = scene.triangles[sceneIndex_[i]];
        const glm::vec3* v[3] = {&t.v0, &t.v1, &t.v2};
        for (std::size_t k = 0; k < 3; ++k) {
            for (std::size_t a = 0; a < 3; ++a) {
                vertices[9 * i + 3 * k + a] = (*v[k])[static_cast<glm::length_t>(a)];
            }
            indices[3 * i + k] = static_cast<unsigned>(3 * i + k);
        }
    }
    rtcCommitGeometry(geometry_);
    return true;
}

bool EmbreeScene::build() {
    const FlushDenormals flush;
    const auto start = std::chrono::steady_clock::now();
    if (scene_) {
        rtcReleaseScene(scene_);
        scene_ = nullptr;
    }
    const std::int64_t before = deviceBytes_.load();
    scene_ = rtcNewScene(device_);
    if (geometry_) {
        rtcAttachGeometry(scene_, geometry_);
    }
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
        error_ = "Embree: the scene build failed";
        return false;
    }
    memoryBytes_ = grownBy(before, deviceBytes_.load());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (buildSeconds_ == 1e30) {
        firstBuildSeconds_ = seconds;
    }
    buildSeconds_ = std::min(buildSeconds_, seconds);
    return true;
}

EmbreeScene::~EmbreeScene() {
    if (scene_) {
        rtcReleaseScene(scene_);
    }
    if (geometry_) {
        rtcReleaseGeometry(geometry_);
    }
    if (device_) {
        rtcReleaseDevice(device_);
    }
}

} // namespace raylab::bench
