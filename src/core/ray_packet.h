#pragma once
// Up to 8 rays, and their hits, in structure-of-arrays form: field f of lane i is f[i], so one
// AVX2 register loads one field of all 8 rays. This is the form the renderer's packet path keeps
// its rays in from generation (PrimaryRays::through8) through tracing (bvh_packet.h) to shading
// (shadeLab8), with no conversion to and from Ray records on the way.

#include "ray.h"

#include <cstdint>

namespace raylab {

inline constexpr int kPacketSize = 8;

struct alignas(32) RayPacket {
    float origin[3][kPacketSize];    // [axis][lane]
    float direction[3][kPacketSize]; // [axis][lane]
    float tMin[kPacketSize];
    float tMax[kPacketSize];
    unsigned lanes = 0; // bit i set: lane i holds a ray; the other lanes are never read back

    // No rays, every field zero.
    RayPacket() : origin{}, direction{}, tMin{}, tMax{} {}
    // No rays, the fields left unset: for code that stores every field of every lane next (a
    // packet on the stack of a hot loop need not be zeroed first).
    struct Unset {};
    explicit RayPacket(Unset) {}

    Ray ray(int i) const {
        return Ray{{origin[0][i], origin[1][i], origin[2][i]},
                   {direction[0][i], direction[1][i], direction[2][i]},
                   tMin[i],
                   tMax[i]};
    }
    void set(int i, const Ray& ray) {
        for (int a = 0; a < 3; ++a) {
            origin[a][i] = ray.origin[a];
            direction[a][i] = ray.direction[a];
        }
        tMin[i] = ray.tMin;
        tMax[i] = ray.tMax;
        lanes |= 1u << i;
    }
};

// The hits of a RayPacket's lanes; a lane without a hit (or without a ray) reads as Hit{}.
struct alignas(32) HitPacket {
    float t[kPacketSize];
    float u[kPacketSize];
    float v[kPacketSize];
    uint32_t triangle[kPacketSize];

    HitPacket() { clear(); }
    // The lanes left unset: for a packet that closestHit8 fills next (it writes every lane).
    explicit HitPacket(RayPacket::Unset) {}
    void clear() {
        for (int i = 0; i < kPacketSize; ++i) {
            set(i, Hit{});
        }
    }
    Hit hit(int i) const { return Hit{t[i], u[i], v[i], triangle[i]}; }
    void set(int i, const Hit& h) {
        t[i] = h.t;
        u[i] = h.u;
        v[i] = h.v;
        triangle[i] = h.triangle;
    }
};

// Lanes [0, count) of a packet, 0 <= count <= kPacketSize.
constexpr unsigned firstLanes(int count) { return (1u << count) - 1u; }

// Whether packets[0, count) are a full block of rays: kPacketSize packets (the rows of an 8 x 8
// pixel block, or its 4 x 2 halves of tiles) of kPacketSize lanes each.
inline bool fullBlock(const RayPacket* packets, int count) {
    if (count != kPacketSize) {
        return false;
    }
    for (int k = 0; k < count; ++k) {
        if (packets[k].lanes != firstLanes(kPacketSize)) {
            return false;
        }
    }
    return true;
}

} // namespace raylab
