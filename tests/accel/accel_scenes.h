#pragma once
// Scenes and rays for the BVH tests, all from fixed seeds.

#include "core/ray.h"
#include "core/scene.h"

#include <cstdint>
#include <random>
#include <vector>

namespace raylab::accel_test {

// `count` triangles with vertices uniform in [-1, 1]^3, each edge at most `size` long-ish.
Scene makeTriangleSoup(int count, float size, uint32_t seed);

// makeTriangleSoup(1500, 0.15, 29) with every triangle three times, the copies at far apart
// indices (the soup reversed, then in order again): each ray must keep the lowest index at equal t.
Scene makeTripledSoup();

// makeTriangleSoup(1000, 0.2, 3) with a NaN vertex, an infinite vertex, a zero-area triangle and
// a collinear one.
Scene makeSoupWithDegenerateTriangles();

// A height field z = h(x, y) over [-1, 1]^2 on an n x n grid of quads (2 n^2 triangles).
Scene makeHeightField(int n, uint32_t seed);

// A closed tessellated sphere (shared vertices moved radially by up to `perturbation`).
Scene makeClosedSphere(int rings, int segments, float radius, float perturbation, uint32_t seed);

// Rays from random points in [-2, 2]^3 towards random points in [-1, 1]^3 (unit directions).
std::vector<Ray> makeRandomRays(int count, uint32_t seed);

// Rays from random points in [-extent, extent]^3 along +-x, +-y, +-z (other components +-0).
std::vector<Ray> makeAxisAlignedRays(int count, float extent, uint32_t seed);

} // namespace raylab::accel_test
