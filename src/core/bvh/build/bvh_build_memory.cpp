#include "bvh/build/bvh_build_memory.h"

namespace raylab {

void BvhBuildMemory::Arrays::clear() {
    records.clear();
    spare.clear();
    binaryNodes.clear();
    sceneIndices.clear();
    spans.clear();
    subtreeNodes.clear();
    subtreeLeaves.clear();
    collapse.nodes.clear();
    collapse.leaves.clear();
}

std::size_t BvhBuildMemory::Arrays::bytes() const {
    return (records.capacity() + spare.capacity()) * sizeof(PrimRecord) +
           binaryNodes.capacity() * sizeof(BvhNode) + sceneIndices.capacity() * sizeof(uint32_t) +
           spans.capacity() * sizeof(LeafSpan) + subtreeNodes.capacity() * sizeof(BvhNode) +
           subtreeLeaves.capacity() * sizeof(uint32_t) +
           collapse.nodes.capacity() * sizeof(BvhWideNode) +
           collapse.leaves.capacity() * sizeof(LeafPlacement);
}

BuildTeam& BvhBuildMemory::Arrays::teamOf(int threads) {
    if (!team || team->size() != threads) {
        team.reset(); // its threads joined before the new team's start
        team = std::make_unique<BuildTeam>(threads);
    }
    return *team;
}

BvhBuildMemory::BvhBuildMemory() : arrays_(std::make_unique<Arrays>()) {}
BvhBuildMemory::~BvhBuildMemory() = default;
BvhBuildMemory::BvhBuildMemory(BvhBuildMemory&&) noexcept = default;
BvhBuildMemory& BvhBuildMemory::operator=(BvhBuildMemory&&) noexcept = default;

BvhBuildMemory::Arrays& BvhBuildMemory::arrays() {
    if (!arrays_) {
        arrays_ = std::make_unique<Arrays>();
    }
    return *arrays_;
}

std::size_t BvhBuildMemory::bytes() const { return arrays_ ? arrays_->bytes() : 0; }

} // namespace raylab
