#pragma once
// Ray sets for the packet tests: coherent ones (a camera's rays row by row, the shadow rays of
// their hits towards a point light) and ones that split a packet (mixed permutations, invalid
// rays).

#include "core/bvh/bvh.h"
#include "core/camera.h"
#include "core/ray.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace raylab::accel_test {

// Camera rays through the pixel centres of a width x height image, row by row (as the renderer
// makes them: a run of 8 along a row is one packet).
std::vector<Ray> cameraRays(const Camera& camera, int width, int height);

// Shadow rays from the closest hits of `rays` towards `light` (eps = 1e-3, as the lab's).
std::vector<Ray> shadowRaysOf(const Bvh& bvh, const std::vector<Ray>& rays, const glm::vec3& light);

// `count` rays from random points in [-0.5, 0.5]^3, cycling through 8 directions along every
// axis, both signs and diagonals: with `perLane`, neighbouring rays differ (each packet of 8
// holds several ray permutations), else runs of 8 share one direction.
std::vector<Ray> mixedDirectionRays(int count, bool perLane, uint32_t seed);

// Makes every third ray invalid in one of five ways (zero direction, NaN origin, infinite
// direction, NaN tMax, NaN tMin).
void invalidateEveryThird(std::vector<Ray>& rays);

} // namespace raylab::accel_test
