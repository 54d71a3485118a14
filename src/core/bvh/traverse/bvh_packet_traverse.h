#pragma once
// The AVX2 packet traversal of the 8-wide BVH (internal to core). Callers check
// bvh.wideNodes is not empty.

#include "bvh/bvh.h"
#include "bvh/bvh_packet.h"
#include "ray_packet.h"

namespace raylab {

// Traces, as one packet, the valid rays of rays.lanes that share the most common ray
// permutation of the watertight test (WatertightRay::kx, ky, kz). Every lane of hits is written:
// Hit{} unless the lane was traced and found a triangle; `occluded` gets the traced lanes that
// hit something. Returns the lanes it did not answer (valid rays with another permutation), for
// the single-ray path. With `last`, the any-hit test tests last's triangle and block first and
// leaves in it a triangle that occluded a lane (LastOccluder).
unsigned closestHitPacket(const Bvh& bvh, const RayPacket& rays, HitPacket& hits);
unsigned anyHitPacket(const Bvh& bvh, const RayPacket& rays, unsigned& occluded,
                      LastOccluder* last = nullptr);

// closestHitPacket of each of the eight RayPackets rays[0, 8) in one walk of the BVH (the camera
// rays of an 8 x 8 block): every lane of hits[0, 8) is written; returns the lanes left for the
// single-ray path (bit 8 k + i: lane i of rays[k]). With `walks`, adds to it the leaves the walk
// entered and the packets it tested in them (CameraWalks).
uint64_t closestHitEightPackets(const Bvh& bvh, const RayPacket* rays, HitPacket* hits,
                                CameraWalks* walks = nullptr);

} // namespace raylab
