#pragma once
// The AVX2 packet traversal of the 8-wide BVH (internal to core). Callers check
// bvh.wideNodes is not empty.

#include "bvh.h"
#include "ray.h"

namespace raylab {

// Traces, as one packet, the valid rays of rays[0, count) (1 <= count <= 8) that share the most
// common ray permutation of the watertight test (WatertightRay::kx, ky, kz), and writes their
// hits[i] (occluded[i]); rays WatertightRay calls invalid get Hit{} (false). Returns the lanes
// it did not answer (valid rays with another permutation), for the single-ray path.
unsigned closestHitPacket(const Bvh& bvh, const Ray* rays, int count, Hit* hits);
unsigned anyHitPacket(const Bvh& bvh, const Ray* rays, int count, bool* occluded);

} // namespace raylab
