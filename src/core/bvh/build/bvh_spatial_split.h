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
#include "bvh/build/bvh_binning.h"
#include "scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab {

inline constexpr int kSpatialBins = 16;

// The plane between spatial bin i - 1 and bin i (0 < i < kSpatialBins) of [lower, lower +
// extent] on the binned axis; plane 0 is `lower` itself. Bin i's slab lies between planes i and
// i + 1, but for the outer bins, which are open below (bin 0) and above (the last).
inline float spatialPlane(float lower, float extent, int i) {
    return lower + extent * (static_cast<float>(i) / static_cast<float>(kSpatialBins));
}

struct SpatialSplit {
    int axis = -1;           // -1: none found
    float position = 0.0f;   // the plane x[axis] = position
    float cost = kInfinity;  // A(left) N(left) + A(right) N(right), as the object split's
    uint32_t references = 0; // N(left) + N(right) estimated by the bins
    // Found from a sample of the node's references (cost and references scaled to the node's):
    // the split made must then be checked against the object split (bvh_build_subtree.h).
    bool sampled = false;
};

// The spatial bins of some references along one axis: per bin, how many references start and
// end in it and the box of their parts in it, each part taken as the reference's box cut to
// the bin's slab (a box around the triangle's own part, which would have to be clipped out of
// it: that clipping took most of Sponza's build, for trees that traced no faster). The SAH cost
// the bins give a plane is then an upper estimate of that of the split the plane makes, whose
// references applySpatialSplit clips exactly. min, max and sums are exact, so bins of parts of
// a node merged in a fixed order equal the bins of the whole. Cache-line aligned, as BinSet.
struct alignas(64) SpatialBins {
    SseBox box[kSpatialBins];
    uint32_t entering[kSpatialBins] = {};
    uint32_t leaving[kSpatialBins] = {};
    void merge(const SpatialBins& other);
};

// Adds refs first[0], first[stride], first[2 stride] ... before `last` (whose boxes lie in
// `bounds`, the node's) to `bins`, over kSpatialBins planes across `axis`: a reference enters
// the bin of its lower bound and leaves the bin of its upper (binOf), and each bin from the one
// to the other is extended by the reference's box intersected with the bin's slab.
void binSpatial(const PrimRecord* first, const PrimRecord* last, const Aabb& bounds, int axis,
                SpatialBins& bins, std::size_t stride = 1);

// The best spatial split across `axis` of a node with these bins and bounds.
SpatialSplit bestSpatialSplit(const SpatialBins& bins, const Aabb& bounds, int axis);

// How many references a spatial split put on each side.
struct SpatialSides {
    std::size_t left = 0, right = 0;
};

// Writes refs [first, last) to left[0..) and right[0..) by split's plane, cutting the
// references that cross it in two, each side in the order of the input, and adds what it writes
// to the sides' bounds. A reference goes to one side or to both, so each side needs room for
// (last - first) records; left and right must not overlap each other or the input.
SpatialSides applySpatialSplit(const Scene& scene, const PrimRecord* first, const PrimRecord* last,
                               const SpatialSplit& split, float slack, PrimRecord* left,
                               PrimRecord* right, RecordBounds& leftBounds,
                               RecordBounds& rightBounds);

// applySpatialSplit into one room of roomSize >= last - first records, which must not overlap the
// input: the left side from room[0] up, the right side from room[roomSize - 1] down, so that the
// right side needs no array of its own (the room is the children's: bvh_build_subtree.cpp).
// When the sides fit (left + right <= roomSize), the left side is room[0, left) and the right
// side room[roomSize - right, roomSize), each in the order of the input; else the room holds
// nothing to use, and nothing outside it was written.
SpatialSides applySpatialSplitInRoom(const Scene& scene, const PrimRecord* first,
                                     const PrimRecord* last, const SpatialSplit& split, float slack,
                                     PrimRecord* room, std::size_t roomSize,
                                     RecordBounds& leftBounds, RecordBounds& rightBounds);
// What applySpatialSplit would write, without writing it: the sides' sizes, and their records
// added to the sides' bounds.
SpatialSides countSpatialSplit(const Scene& scene, const PrimRecord* first, const PrimRecord* last,
                               const SpatialSplit& split, float slack, RecordBounds& leftBounds,
                               RecordBounds& rightBounds);

} // namespace raylab
