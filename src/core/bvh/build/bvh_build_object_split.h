#pragma once
// Object splits of the binned SAH build (internal to bvh_build.cpp): the best plane between two
// bins of the centroids, found from the bins (bvh_binning.h), and the partition of references
// by it.

#include "bvh/build/bvh_binning.h"

#include <cstdint>

namespace raylab {

struct ObjectSplit {
    int axis = -1;            // -1: none (every centroid in one bin on every axis)
    int bin = 0;              // first bin of the right side
    float cost = kInfinity;   // A(left) N(left) + A(right) N(right)
    float overlapArea = 0.0f; // surface of the intersection of the children's boxes
    glm::vec3 lower{0.0f};    // the centroid bounds' lower corner ...
    glm::vec3 scale{0.0f};    // ... and the scale binOf (bvh_binning.h) bins with
    int bins = 0;             // ... into this many bins per axis
    uint32_t leftCount = 0;   // references on the left side
};

// The bin frame of a node: centroids' lower corner and scale per axis (0 on a flat axis).
ObjectSplit objectBinFrame(const Aabb& centroids, int bins);

// The cheapest split of `count` references binned in `frame` (objectBinFrame), with a child
// on each side; axis < 0 when there is none.
ObjectSplit bestObjectSplit(const BinSet& bins, uint32_t count, const ObjectSplit& frame);

// How far a node's references reach beyond their bins (binned in `frame`, the node's box
// `bounds`): the largest over the binned axes of the summed extents of the non-empty bins'
// boxes along the axis over the node's extent, less 1. About 0 for references much smaller
// than a bin, 1 or more where references cross bins.
float binOverreach(const BinSet& bins, const ObjectSplit& frame, const Aabb& bounds);

// References of [first, last) whose centroids the split puts on the left.
uint32_t leftCountOf(const BinSet& bins, const ObjectSplit& split);

// Copies [first, last) to left[0..) and right[0..) by the split's side, each side in the order
// of the input (a stable partition), and adds them to the sides' bounds.
void partitionRecords(const PrimRecord* first, const PrimRecord* last, const ObjectSplit& split,
                      PrimRecord* left, PrimRecord* right, RecordBounds& leftBounds,
                      RecordBounds& rightBounds);

// Orders [first, first + count) so its lower half along the axis of the largest centroid extent
// (`bounds` are the references') comes first, ties by scene index; leaves it when the centroids
// all coincide. Splitting there always gives two non-empty halves.
void medianOrder(PrimRecord* first, uint32_t count, const RecordBounds& bounds);

} // namespace raylab
