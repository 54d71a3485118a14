// Packet dispatch: the scalar path when there is no SIMD form, and the exact single-ray path for
// the lanes the packet traversal leaves out (rays whose watertight permutation differs from the
// packet's).

#include "bvh_packet.h"

#include "bvh_packet_traverse.h"

namespace raylab {

void closestHit8(const Bvh& bvh, const Ray* rays, int count, Hit* hits) {
    if (count <= 0) {
        return;
    }
    if (bvh.wideNodes.empty()) {
        for (int i = 0; i < count; ++i) {
            hits[i] = closestHit(bvh, rays[i]);
        }
        return;
    }
    for (unsigned m = closestHitPacket(bvh, rays, count, hits); m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        hits[i] = closestHit(bvh, rays[i]);
    }
}

void anyHit8(const Bvh& bvh, const Ray* rays, int count, bool* occluded) {
    if (count <= 0) {
        return;
    }
    if (bvh.wideNodes.empty()) {
        for (int i = 0; i < count; ++i) {
            occluded[i] = anyHit(bvh, rays[i]);
        }
        return;
    }
    for (unsigned m = anyHitPacket(bvh, rays, count, occluded); m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        occluded[i] = anyHit(bvh, rays[i]);
    }
}

} // namespace raylab
