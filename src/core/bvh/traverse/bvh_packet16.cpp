// 16-ray packet dispatch: the AVX-512 traversal (bvh_packet16_avx512.cpp) where the CPU has it,
// else two 8-ray packets; the lanes the packet leaves out (another ray permutation) go to the
// exact single-ray path, as in closestHit8 / anyHit8.

#include "bvh/bvh_packet.h"
#include "bvh/traverse/bvh_packet16_traverse.h"
#include "bvh/traverse/bvh_packet_traverse.h"

namespace raylab {

bool bvhPacket16Supported() {
#if defined(__x86_64__) || defined(__i386__)
    return bvhSimdSupported() && __builtin_cpu_supports("avx512f");
#else
    return false;
#endif
}

namespace {

Packet16Path defaultPath() {
    static const bool avx512 = bvhPacket16Supported();
    return avx512 ? Packet16Path::Avx512 : Packet16Path::TwoPackets8;
}

// Ray i of the 16 lanes.
Ray rayOf(const RayPacket& low, const RayPacket& high, int i) {
    return i < kPacketSize ? low.ray(i) : high.ray(i - kPacketSize);
}

} // namespace

void closestHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, HitPacket& lowHits,
                  HitPacket& highHits, Packet16Path path) {
    if (path == Packet16Path::TwoPackets8 || bvh.wideNodes.empty()) {
        closestHit8(bvh, low, lowHits);
        closestHit8(bvh, high, highHits);
        return;
    }
    const unsigned single = closestHitPacket16(bvh, low, high, lowHits, highHits);
    for (unsigned m = single; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        HitPacket& hits = i < kPacketSize ? lowHits : highHits;
        hits.set(i % kPacketSize, closestHit(bvh, rayOf(low, high, i)));
    }
}

void closestHit64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits, Packet16Path path,
                  CameraWalks* walks) {
    if (bvh.wideNodes.empty()) {
        for (int k = 0; k < kPacketSize; k += 2) {
            closestHit16(bvh, rays[k], rays[k + 1], hits[k], hits[k + 1], path);
        }
        return;
    }
    if (path == Packet16Path::TwoPackets8 && walks != nullptr && walks->eightWalks()) {
        for (int k = 0; k < kPacketSize; ++k) {
            closestHit8(bvh, rays[k], hits[k]);
        }
        return;
    }
    const uint64_t single = path == Packet16Path::TwoPackets8
                                ? closestHitEightPackets(bvh, rays, hits, walks)
                                : closestHitPacket64(bvh, rays, hits);
    for (uint64_t m = single; m != 0; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        const int k = i / kPacketSize, lane = i % kPacketSize;
        hits[k].set(lane, closestHit(bvh, rays[k].ray(lane)));
    }
}

unsigned anyHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, Packet16Path path,
                  LastOccluder* last) {
    if (path == Packet16Path::TwoPackets8 || bvh.wideNodes.empty()) {
        if (last == nullptr) {
            return anyHit8(bvh, low) | anyHit8(bvh, high) << kPacketSize;
        }
        const unsigned lowOccluded = anyHit8(bvh, low, *last);
        return lowOccluded | anyHit8(bvh, high, *last) << kPacketSize;
    }
    unsigned occluded = 0;
    const unsigned single = anyHitPacket16(bvh, low, high, occluded, last);
    for (unsigned m = single; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        if (anyHit(bvh, rayOf(low, high, i))) {
            occluded |= 1u << i;
        }
    }
    return occluded;
}

void closestHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, HitPacket& lowHits,
                  HitPacket& highHits) {
    closestHit16(bvh, low, high, lowHits, highHits, defaultPath());
}

void closestHit64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits) {
    closestHit64(bvh, rays, hits, defaultPath());
}

void closestHit64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits, CameraWalks& walks) {
    closestHit64(bvh, rays, hits, defaultPath(), &walks);
}

unsigned anyHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high) {
    return anyHit16(bvh, low, high, defaultPath());
}

unsigned anyHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, LastOccluder& last) {
    return anyHit16(bvh, low, high, defaultPath(), &last);
}

} // namespace raylab
