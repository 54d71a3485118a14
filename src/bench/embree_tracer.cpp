#include "embree_tracer.h"

#include <chrono>
#include <embree3/rtcore.h>

namespace raylab::bench {

namespace {

RTCRay toEmbree(const Ray& ray) {
    RTCRay r{};
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = ray.tMin;
    r.tfar = ray.tMax;
    r.mask = 0xffffffffu;
    r.flags = 0;
    return r;
}

} // namespace

EmbreeTracer::EmbreeTracer(const Scene& scene) {
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device) {
        error_ = "Embree: cannot create a device";
        return;
    }
    device_ = device;
    std::vector<const Triangle*> valid;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        if (isValidTriangle(scene.triangles[i])) {
            valid.push_back(&scene.triangles[i]);
            sceneIndex_.push_back(static_cast<uint32_t>(i));
        }
    }
    const auto start = std::chrono::steady_clock::now();
    RTCScene rtcScene = rtcNewScene(device);
    scene_ = rtcScene;
    if (!valid.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), 3 * valid.size()));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), valid.size()));
        if (!vertices || !indices) {
            error_ = "Embree: cannot allocate the geometry buffers";
            rtcReleaseGeometry(geometry);
            return;
        }
        for (std::size_t i = 0; i < valid.size(); ++i) {
            const glm::vec3* v[3] = {&valid[i]->v0, &valid[i]->v1, &valid[i]->v2};
            for (int k = 0; k < 3; ++k) {
                for (int a = 0; a < 3; ++a) {
                    vertices[9 * i + 3 * static_cast<std::size_t>(k) +
                             static_cast<std::size_t>(a)] = (*v[k])[a];
                }
                indices[3 * i + static_cast<std::size_t>(k)] =
                    static_cast<unsigned>(3 * i + static_cast<std::size_t>(k));
            }
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(rtcScene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(rtcScene);
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE) {
        error_ = "Embree: the scene build failed";
    }
}

EmbreeTracer::~EmbreeTracer() {
    if (scene_) {
        rtcReleaseScene(static_cast<RTCScene>(scene_));
    }
    if (device_) {
        rtcReleaseDevice(static_cast<RTCDevice>(device_));
    }
}

void EmbreeTracer::traceTile(const BenchRays& rays, std::size_t tile, std::vector<Hit>& hits,
                             std::vector<uint8_t>& occluded) const {
    const auto scene = static_cast<RTCScene>(scene_);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
        RTCRayHit rayHit{};
        rayHit.ray = toEmbree(rays.primary[i]);
        rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rayHit);
        Hit& hit = hits[i];
        if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
            hit = Hit{};
        } else {
            hit = Hit{rayHit.ray.tfar, rayHit.hit.u, rayHit.hit.v, sceneIndex_[rayHit.hit.primID]};
        }
    }
    for (std::size_t j = rays.shadowOffset[tile]; j < rays.shadowOffset[tile + 1]; ++j) {
        RTCRay ray = toEmbree(rays.shadow[j]);
        rtcOccluded1(scene, &context, &ray);
        // Embree marks an occluded ray by setting tfar to -inf.
        occluded[j] = ray.tfar < 0.0f ? 1 : 0;
    }
}

} // namespace raylab::bench
