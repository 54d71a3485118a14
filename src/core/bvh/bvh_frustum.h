#pragma once
// Frustum culling for a group of coherent packets: the camera rays of an 8 x 8 pixel block, or
// their shadow rays towards one point light. A pyramid that holds every ray of the group is
// walked through the 8-wide BVH once, keeping the triangles that may lie inside it; each packet
// then tests just those triangles, with no traversal of its own (where the CPU has AVX-512, two
// packets at a time, each triangle against their 16 rays at once). When the pyramid holds more
// than kMaxFrustumCandidates triangles (a finely tessellated mesh seen from afar), the caller
// traces the packets as usual (bvh_packet.h).
//
// Exactness: the pyramid's planes are pushed outwards by `tolerance`, a distance far above the
// rounding of the triangle test and of the ray arithmetic, so every triangle that the packet
// traversal could find for some ray of the group is a candidate. Candidates are tested with the
// packet traversal's own triangle test and (t, triangle index) rule, so each lane's answer is
// closestHit8's or anyHit8's bit for bit.

#include "bvh/bvh.h"
#include "camera.h"
#include "ray_packet.h"

#include <cstdint>
#include <glm/vec3.hpp>

namespace raylab {

inline constexpr int kMaxFrustumPlanes = 5;
inline constexpr int kMaxFrustumCandidates = 32;

// The region where dot(normal[j], p - apex) + offset[j] >= -tolerance for every plane j
// (normals of unit length, distances in world units).
struct RayFrustum {
    glm::vec3 apex{0.0f};
    int planeCount = 0;
    glm::vec3 normal[kMaxFrustumPlanes]{};
    float offset[kMaxFrustumPlanes]{};
    float tolerance = 0.0f;
};

// The planes' outward push for a pyramid with its apex at `apex` over the scene of `bvh` (which
// must have nodes): 4e-5 times the largest |coordinate| of its node boxes and the apex, about 170
// float ulps of it (1e-5 is about 170 float ulps of a coordinate), far above the few ulps of
// rounding in the ray arithmetic, the triangle test and the plane test.
float frustumTolerance(const Bvh& bvh, const glm::vec3& apex);

// Leaf triangles of the 8-wide BVH: triangle lane[i] of bvh.triangleBlocks[block[i]].
struct FrustumCandidates {
    int count = 0;
    uint32_t block[kMaxFrustumCandidates];
    uint8_t lane[kMaxFrustumCandidates];
};

// A pyramid holding every ray (tMin < t) of packets[0, count), which must share one origin, the
// pyramid's apex. False when there is none of use: the origins differ, a direction is not finite
// or lies more than about 78 degrees from the group's mean direction, the BVH has no 8-wide form
// or the CPU no AVX2.
bool frustumOfRays(const Bvh& bvh, const RayPacket* packets, int count, RayFrustum& frustum);

// A rectangle of image points in pixel units (y down, as PrimaryRays::through takes them):
// x0 <= px <= x1 and y0 <= py <= y1.
struct ImageRect {
    float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
};

// A pyramid holding every ray camera.through(px, py) (or through8) for (px, py) in `rect`: the
// four planes through the camera's position and the rectangle's edges, exact in real arithmetic
// and computed from the camera's basis alone (no ray is read). False when the BVH has no 8-wide
// form, the CPU no AVX2, the rectangle is empty or not finite (x0 <= x1, y0 <= y1 fails), or
// the camera gives no finite plane.
bool frustumOfImageRect(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect,
                        RayFrustum& frustum);

// True when no ray camera.through(px, py) (or through8) with (px, py) in `rect` can enter a child
// of the BVH's root, the rectangle's pyramid (frustumOfImageRect) lying outside all of them: then
// each of those rays misses every triangle, and a block of pixels that sees only the background
// is answered without its rays. False wherever frustumOfImageRect is.
bool imageRectMissesScene(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect);

// A pyramid with its apex at `end` holding the segment from each ray's origin to `end`, for rays
// that run from their origin towards `end` and stop before it (tMax at most the distance to
// `end`: shadow rays towards a point light). False as for frustumOfRays.
bool frustumOfSegments(const Bvh& bvh, const RayPacket* packets, int count, const glm::vec3& end,
                       RayFrustum& frustum);

// The leaf triangles that may lie in the frustum (a superset of those that do). False when there
// are more than kMaxFrustumCandidates; `candidates` is then incomplete.
bool frustumCandidates(const Bvh& bvh, const RayFrustum& frustum, FrustumCandidates& candidates);

// closestHit8(bvh, rays, hits) and anyHit8(bvh, rays), exactly, for rays that lie in the frustum
// the candidates were collected for.
void closestHitCandidates(const Bvh& bvh, const FrustumCandidates& candidates,
                          const RayPacket& rays, HitPacket& hits);
unsigned anyHitCandidates(const Bvh& bvh, const FrustumCandidates& candidates,
                          const RayPacket& rays);

// A block's tracing as the renderer does it: closestHit8 for each of rays[0, count) (camera
// rays from one origin, count <= kPacketSize), through one frustum's candidates when it fits.
// Returns true when the candidates were used.
bool closestHitBlock(const Bvh& bvh, const RayPacket* rays, int count, HitPacket* hits);

// The same for rays made by camera.through8 from image points in `rect` (a block's pixels), with
// the frustum of the rectangle (frustumOfImageRect) instead of one fitted to the rays.
bool closestHitBlock(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect,
                     const RayPacket* rays, int count, HitPacket* hits);

// The same for any hits: occluded[k] = anyHit8(bvh, rays[k]), for rays that run from their
// origin towards `end` and stop short of it (frustumOfSegments' contract).
bool anyHitBlock(const Bvh& bvh, const RayPacket* rays, int count, const glm::vec3& end,
                 unsigned* occluded);

} // namespace raylab
