#pragma once
// Procedural test geometry shared by the core and acceleration tests.

#include "core/scene.h"

#include <cstdint>

namespace raylab::test {

// A closed UV sphere (two poles, `rings` latitude bands, `segments` longitudes) whose shared
// vertices are moved radially by up to `perturbation` (relative) with a fixed seed. Every edge is
// shared by exactly two triangles, so a watertight test lets no ray from inside escape.
Scene makePerturbedSphere(int rings, int segments, float radius, float perturbation, uint32_t seed);

// A square [-half, half]^2 in the plane z = depth, as two triangles, with the given diffuse colour.
Scene makeQuadScene(float half, float depth, glm::vec3 diffuse);

// Appends an axis-aligned square of half-size `half` centred at `center`, facing z, as two
// triangles with material `material`.
void addSquareZ(Scene& scene, glm::vec3 center, float half, uint32_t material);

} // namespace raylab::test
