// Packet dispatch: the scalar path when there is no SIMD form, and the exact single-ray path for
// the lanes the packet traversal leaves out (rays whose watertight permutation differs from the
// packet's).

#include "bvh/bvh_packet.h"

#include "bvh/traverse/bvh_packet_traverse.h"

namespace raylab {

void closestHit8(const Bvh& bvh, const RayPacket& rays, HitPacket& hits) {
    unsigned single = rays.lanes;
    if (!bvh.wideNodes.empty() && rays.lanes != 0) {
        single = closestHitPacket(bvh, rays, hits);
    } else {
        hits.clear();
    }
    for (unsigned m = single; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        hits.set(i, closestHit(bvh, rays.ray(i)));
    }
}

namespace {
unsigned anyHit8(const Bvh& bvh, const RayPacket& rays, LastOccluder* last) {
    unsigned occluded = 0;
    unsigned single = rays.lanes;
    if (!bvh.wideNodes.empty() && rays.lanes != 0) {
        single = anyHitPacket(bvh, rays, occluded, last);
    }
    for (unsigned m = single; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        if (anyHit(bvh, rays.ray(i))) {
            occluded |= 1u << i;
        }
    }
    return occluded;
}
} // namespace

unsigned anyHit8(const Bvh& bvh, const RayPacket& rays) { return anyHit8(bvh, rays, nullptr); }

unsigned anyHit8(const Bvh& bvh, const RayPacket& rays, LastOccluder& last) {
    return anyHit8(bvh, rays, &last);
}

namespace {
RayPacket packetOf(const Ray* rays, int count) {
    RayPacket packet;
    for (int i = 0; i < count; ++i) {
        packet.set(i, rays[i]);
    }
    return packet;
}
} // namespace

void closestHit8(const Bvh& bvh, const Ray* rays, int count, Hit* hits) {
    if (count <= 0) {
        return;
    }
    HitPacket packetHits;
    closestHit8(bvh, packetOf(rays, count), packetHits);
    for (int i = 0; i < count; ++i) {
        hits[i] = packetHits.hit(i);
    }
}

void anyHit8(const Bvh& bvh, const Ray* rays, int count, bool* occluded) {
    if (count <= 0) {
        return;
    }
    const unsigned answers = anyHit8(bvh, packetOf(rays, count));
    for (int i = 0; i < count; ++i) {
        occluded[i] = ((answers >> i) & 1u) != 0;
    }
}

} // namespace raylab
