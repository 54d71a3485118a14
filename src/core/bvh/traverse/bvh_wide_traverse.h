#pragma once
// The AVX2 traversal of the 8-wide BVH (internal to core). Callers check bvh.wideNodes is not
// empty (it is only built on CPUs with AVX2).

#include "bvh/bvh.h"
#include "triangle_intersection.h"

#include <cstddef>

namespace raylab {

// Same contracts and answers as closestHitScalar / anyHitScalar.
// Rays that WatertightRay calls invalid hit nothing.
Hit closestHitWide(const Bvh& bvh, const Ray& ray);
bool anyHitWide(const Bvh& bvh, const Ray& ray);
// The same, adding what they visit to `cost`.
Hit closestHitWideCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost);
bool anyHitWideCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost);

// How many rays closestHitsInterleaved walks at once. On the dragon's bounce rays, 1 thread: 12
// walks 3.8 Mrays/s, 8 walks 3.6-3.7, one by one 3.1-3.3 (16 were no faster than 12).
inline constexpr int kInterleavedRays = 12;

// hits[i] = closestHitWide(bvh, rays[i]) for i < count, bit for bit, the rays walked
// kInterleavedRays at a time: one node or leaf of each in turn, each walk's next node prefetched
// as soon as it is known, so that one ray's wait on memory overlaps the others' work.
void closestHitsInterleaved(const Bvh& bvh, const Ray* rays, std::size_t count, Hit* hits);

} // namespace raylab
