#pragma once
// What BvhBuildMemory (bvh.h) keeps between builds (internal to core): the build's arrays that do
// not end up in the Bvh. rebuildBvh empties them (keeping their capacity) before it uses them.

#include "bvh/build/bvh_binning.h"
#include "bvh/build/bvh_collapse.h"
#include "bvh/bvh.h"

#include <cstdint>

namespace raylab {

struct BvhBuildMemory::Arrays {
    RecordVector records;                       // the references (BuildTask's first room)
    RecordVector spare;                         // ... and their spare room
    UninitialisedVector<BvhNode> binaryNodes;   // when the Bvh keeps only the 8-wide form
    UninitialisedVector<uint32_t> sceneIndices; // of the leaf triangles, for the 8-wide form
    UninitialisedVector<LeafSpan> spans;        // of the binary nodes, for the 8-wide form
    // The subtrees' nodes and leaf references, each subtree in slots of its own (bvh_build.cpp)
    UninitialisedVector<BvhNode> subtreeNodes;
    UninitialisedVector<uint32_t> subtreeLeaves;
    CollapseMemory collapse; // the 8-wide form's subtrees'

    void clear(); // every array empty, its capacity kept
    std::size_t bytes() const;
};

} // namespace raylab
