#pragma once
// shadeLab8's AVX2 stages on either side of the shadow test (internal to core: call them only
// where bvhSimdSupported()), so that a group of packets can trace its shadow rays together
// (shadeLabBlock).

#include "integrators/lab_shading.h"
#include "ray_packet.h"

namespace raylab {

// Set bits of a lane mask (the POPCNT instruction where the CPU has it).
int laneCount(unsigned lanes);

// A packet's radiance both ways the shadow test can go: `lit` for an unshadowed lane (rho * N
// where the light does not reach it anyway), `dark` for an occluded one (rho * N); 0 in the lanes
// without a hit.
struct alignas(32) ShadingBeforeShadow {
    float lit[3][kPacketSize];
    float dark[3][kPacketSize];
};

// Shades the hits of rays (scene triangle indices in hits) up to the shadow test and sets
// shadowRays (every lane that needs one, in the lane of its camera ray; shadowRays.lanes = those
// lanes), counting them in counts.shadow.
void beginShade(const Scene& scene, const RenderSettings& settings, const RayPacket& rays,
                const HitPacket& hits, ShadingBeforeShadow& stage, RayPacket& shadowRays,
                RayCounts& counts);

// The radiance once the shadow rays' answers are known (bit i: lane i's shadow ray is blocked).
void finishShade(const ShadingBeforeShadow& stage, unsigned occluded, RadiancePacket& radiance);

} // namespace raylab
