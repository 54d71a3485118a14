#pragma once
// The lab's method: every ray against every triangle. The reference the BVH is checked against.

#include "ray.h"
#include "scene.h"

namespace raylab {

// Closest hit with ray.tMin < t < ray.tMax. On equal t, the lower triangle index wins.
Hit closestHitBruteForce(const Scene& scene, const Ray& ray);

bool anyHitBruteForce(const Scene& scene, const Ray& ray);

} // namespace raylab
