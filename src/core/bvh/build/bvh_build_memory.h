#pragma once
// What BvhBuildMemory (bvh.h) keeps between builds (internal to core): the build's arrays that do
// not end up in the Bvh. rebuildBvh empties them (keeping their capacity) before it uses them.

#include "bvh/build/bvh_binning.h"
#include "bvh/build/bvh_build_team.h"
#include "bvh/build/bvh_collapse.h"
#include "bvh/bvh.h"

#include <cstdint>
#include <memory>

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
    // The threads of the last build on more than one, asleep between builds (BuildTeam), so that
    // a rebuild does not start and join them again: 0.1-0.3 ms of a 2-thread Sponza build of
    // 9 ms on the Zen 5 (PERFORMANCE.md, "Memory and page faults").
    std::unique_ptr<BuildTeam> team;

    void clear(); // every array empty, its capacity kept
    std::size_t bytes() const;
    // A team of `threads` threads (at least 1): the kept one when it has as many, else a new one
    // kept in its place.
    BuildTeam& teamOf(int threads);
};

} // namespace raylab
