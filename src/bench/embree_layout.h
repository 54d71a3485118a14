#pragma once
// Internal to embree_rays.cpp and embree_packets.cpp: raylab's rays in Embree's ray structures,
// Embree's hits back as raylab's, and the two layouts' constructors.

#include "bench_rays.h"
#include "embree_rays.h"
#include "embree_scene.h"

#include <array>
#include <cstdint>
#include <memory>
#include <numeric>
#include <vector>

namespace raylab::bench {

inline constexpr int kPacketLanes = 16;

// Embree's ray fields from raylab's: the same segment (tnear = tMin, tfar = tMax), every ray
// mask bit set, time 0.
inline void setRay(RTCRay& r, const Ray& ray) {
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.tnear = ray.tMin;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.time = 0.0f;
    r.tfar = ray.tMax;
    r.mask = 0xffffffffu;
    r.id = 0;
    r.flags = 0;
}

inline void setRay(RTCRayHit& r, const Ray& ray) {
    setRay(r.ray, ray);
    r.hit.primID = RTC_INVALID_GEOMETRY_ID;
    r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    r.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

inline void setLane(RTCRay16& r, int l, const Ray& ray) {
    r.org_x[l] = ray.origin.x;
    r.org_y[l] = ray.origin.y;
    r.org_z[l] = ray.origin.z;
    r.tnear[l] = ray.tMin;
    r.dir_x[l] = ray.direction.x;
    r.dir_y[l] = ray.direction.y;
    r.dir_z[l] = ray.direction.z;
    r.time[l] = 0.0f;
    r.tfar[l] = ray.tMax;
    r.mask[l] = 0xffffffffu;
    r.id[l] = 0;
    r.flags[l] = 0;
}

inline void setLane(RTCRayHit16& r, int l, const Ray& ray) {
    setLane(r.ray, l, ray);
    r.hit.primID[l] = RTC_INVALID_GEOMETRY_ID;
    r.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
    r.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
}

inline Hit hitOf(const EmbreeScene& scene, float tfar, float u, float v, unsigned geomID,
                 unsigned primID) {
    return geomID == RTC_INVALID_GEOMETRY_ID ? Hit{} : Hit{tfar, u, v, scene.sceneIndex(primID)};
}

inline RTCIntersectContext intersectContext(bool coherent) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags =
        coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    return context;
}

// For each primary ray, its ray in each set (primary, shadow, bounce), or kNoRay.
inline std::array<std::vector<uint32_t>, 3> setRaysOfPrimary(const BenchRays& rays) {
    std::vector<uint32_t> identity(rays.primary.size());
    std::iota(identity.begin(), identity.end(), 0u);
    return {identity, rayOfPrimary(rays.shadowPrimary, rays.primary.size()),
            rayOfPrimary(rays.bouncePrimary, rays.primary.size())};
}

// Embree's 16-ray packets on 4 x 4 pixel tiles (embree_packets.cpp).
std::unique_ptr<EmbreeRays> makePacketRays(const EmbreeScene& scene, const BenchRays& rays);

} // namespace raylab::bench
