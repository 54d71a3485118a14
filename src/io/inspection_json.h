#pragma once
// A pixel's inspection (core/integrators/pixel_inspection.h) as one JSON object, the output of
// `raylab-render --inspect X,Y`. Keys: pixel [x, y], hit, cost (the camera ray's and the shadow
// ray's BVH nodes visited and triangles tested); for a hit also triangle, material, t,
// point, rho, normal, to_light, distance, cos_theta, D_unshadowed, D, shadow_tested, shadowed,
// blocker ({triangle, t} or null), epsilon, t_max (|r| - eps), visibility, N, E, R, display
// (0-255 per channel), and with the path integrator path (a list of {point, rho, D, adds}).
// Vectors are arrays of three numbers.

#include "core/integrators/pixel_inspection.h"

#include <string>

namespace raylab {

std::string inspectionToJson(const PixelInspection& inspection);

} // namespace raylab
