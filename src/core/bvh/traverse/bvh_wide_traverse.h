#pragma once
// The AVX2 traversal of the 8-wide BVH (internal to core). Callers check bvh.wideNodes is not
// empty (it is only built on CPUs with AVX2).

#include "bvh/bvh.h"
#include "triangle_intersection.h"

namespace raylab {

// Same contracts and answers as closestHitScalar / anyHitScalar.
// Rays that WatertightRay calls invalid hit nothing.
Hit closestHitWide(const Bvh& bvh, const Ray& ray);
bool anyHitWide(const Bvh& bvh, const Ray& ray);
// The same, adding what they visit to `cost`.
Hit closestHitWideCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost);
bool anyHitWideCounted(const Bvh& bvh, const Ray& ray, TraversalCost& cost);

} // namespace raylab
