#pragma once
// A pending node of the 64-ray walks (bvh_packet64_avx2.cpp: eight 8-ray packets;
// bvh_packet64_avx512.cpp: four 16-ray packets), internal to core, and how a node's hit children
// are kept in order on their stack.

#include <cstdint>

namespace raylab::packet_lanes {

struct Entry64 {
    float tNear; // at most the entry distance of each of its lanes
    uint32_t ref;
    uint64_t lanes; // a superset of the lanes whose ray enters the box, one bit per lane of 64
};

// Inserts e into out[0, n), which is sorted nearest last by tNear (the walk pops the nearest
// first), and returns n + 1. out has room for n + 1 entries.
inline int insertNearestLast(Entry64* out, int n, const Entry64& e) {
    int i = n;
    for (; i > 0 && out[i - 1].tNear < e.tNear; --i) {
        out[i] = out[i - 1];
    }
    out[i] = e;
    return n + 1;
}

} // namespace raylab::packet_lanes
