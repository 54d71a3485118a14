#pragma once
// Spatial splits for the binned SAH build (internal to core), after Stich, Friedrich and
// Dietrich, "Spatial Splits in Bounding Volume Hierarchies" (HPG 2009): a node may be split by a
// plane that cuts triangles, a triangle crossing it going to both children with the box of its
// part on each side. This removes the overlap of child boxes that object splits leave when
// large triangles cross the node (architecture: floors, walls, columns).
//
// A reference of a triangle still tests the whole scene triangle, so answers (t, u, v, index)
// are the same wherever the triangle is found.

#include "aabb.h"
#include "bvh_binning.h"
#include "scene.h"

#include <cstdint>
#include <vector>

namespace raylab {

inline constexpr int kSpatialBins = 16;

struct SpatialSplit {
    int axis = -1;           // -1: none found
    float position = 0.0f;   // the plane x[axis] = position
    float cost = kInfinity;  // A(left) N(left) + A(right) N(right), as the object split's
    uint32_t references = 0; // N(left) + N(right) estimated by the bins
};

// The best spatial split of refs (whose boxes lie in `bounds`) over kSpatialBins planes per
// axis. `slack` is splitBox's (bvh_clip.h).
SpatialSplit findSpatialSplit(const Scene& scene, const std::vector<PrimRecord>& refs,
                              const Aabb& bounds, float slack);

// Distributes refs to left and right by split's plane, splitting the references that cross it.
// Returns false (left and right unspecified) when a side would be empty.
bool applySpatialSplit(const Scene& scene, const std::vector<PrimRecord>& refs,
                       const SpatialSplit& split, float slack, std::vector<PrimRecord>& left,
                       std::vector<PrimRecord>& right);

} // namespace raylab
