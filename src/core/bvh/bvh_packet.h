#pragma once
// Packets of up to 8 rays traced together through the BVH: for coherent rays (the primary rays
// of a block of pixels, the shadow rays of their hits towards one light) one traversal serves
// all of them. Every answer is exactly the single-ray one: lane i's hit is closestHit(bvh, ray i)
// bit for bit (t, u, v, triangle), its any-hit answer is anyHit(bvh, ray i).

#include "bvh/bvh.h"
#include "ray_packet.h"

namespace raylab {

// The triangle that last occluded a lane of anyHit8's or anyHit16's packets on one BVH.
// Neighbouring shadow rays towards one light are often blocked by the same triangle
// (PERFORMANCE.md, "The last occluder first"), so each call tests it against its lanes before the
// traversal, and then the other triangles of its block (its neighbours in the BVH) against the
// lanes it leaves open; the traversal traces only the lanes still open. The answers are the same
// as without it: a lane one of those triangles occludes is one the traversal finds occluded. A
// caller keeps one for a run of coherent packets on one BVH (a block's, a tile's); a default-made
// one tests nothing first.
struct LastOccluder {
    static constexpr uint32_t kNone = ~0u;
    uint32_t block = kNone; // index into Bvh::triangleBlocks, or kNone
    int slot = 0;           // the triangle's slot in that block, 0-7
};

// Closest hits of the lanes of rays.lanes; every other lane of hits gets Hit{}. Every lane is
// written, whatever hits held.
void closestHit8(const Bvh& bvh, const RayPacket& rays, HitPacket& hits);

// The lanes of rays.lanes whose ray hits a triangle (bit i: lane i).
unsigned anyHit8(const Bvh& bvh, const RayPacket& rays);

// anyHit8 that tests last's triangle and block first and leaves in `last` a triangle that
// occluded a lane.
unsigned anyHit8(const Bvh& bvh, const RayPacket& rays, LastOccluder& last);

// The same for Ray records: rays[0, count) into hits[0, count) or occluded[0, count),
// 0 <= count <= kPacketSize.
void closestHit8(const Bvh& bvh, const Ray* rays, int count, Hit* hits);
void anyHit8(const Bvh& bvh, const Ray* rays, int count, bool* occluded);

// Packets of 16 rays: two RayPackets, `low` as lanes 0-7 and `high` as lanes 8-15, with the
// same answers as closestHit8 / anyHit8 of each (so as the single rays). Where the CPU has
// AVX-512 (bvhPacket16Supported) they are traced as one packet of 16 rays, else one after the
// other. Coherent rays gain the most: the pixels of two neighbouring rows, or their shadow rays.
void closestHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, HitPacket& lowHits,
                  HitPacket& highHits);

// Packets of 64 rays: rays[0, 8), each pair rays[2w], rays[2w + 1] as closestHit16's low and
// high, into hits[0, 8), with the same answers as closestHit8 of each, traced in one walk of the
// BVH whose node visits serve the 64 rays: as four 16-ray packets where the CPU has AVX-512, else
// as eight 8-ray packets. For the camera rays of a block of 8 x 8 pixels, each pair a 4 x 4 tile
// (tilePixel, lab_shading.h).
void closestHit64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits);

// How closestHit64 traces a tile's full blocks on a CPU with AVX2 but not AVX-512: in the one
// shared walk of eight 8-ray packets, or as eight walks of one packet each (closestHit8). The
// shared walk pays where a block's packets go through the same nodes and leaves (Sponza, where 6
// of the 8 share a leaf on average); where they part ways early, as where triangles are small
// against a block (the dragon and the terrain seen whole: 2.0-2.3 a leaf), it tests children and
// leaves packet by packet anyway and the eight walks are faster (PERFORMANCE.md, "A block's
// camera rays in one walk or eight"). A caller keeps one for the blocks of a tile, on one BVH,
// default-made at the tile's start. A tile starts with the shared walk, which counts the leaves
// it enters and the packets it tests in them; from kLeavesToDecide leaves on, its blocks take
// eight walks while fewer than kPacketsSharingALeaf packets share a leaf on average. Eight walks
// count nothing, so a tile keeps them once chosen. The answers are the same either way; where the
// CPU has AVX-512 the 16-ray packets' shared walk is always taken and nothing is counted.
struct CameraWalks {
    static constexpr uint64_t kLeavesToDecide = 32;
    static constexpr uint64_t kPacketsSharingALeaf = 3;
    uint64_t leaves = 0;          // leaves the tile's shared walks entered
    uint64_t packetLeafTests = 0; // packets tested in them, 1 to 8 a leaf

    bool eightWalks() const {
        return leaves >= kLeavesToDecide && packetLeafTests < kPacketsSharingALeaf * leaves;
    }
};

// closestHit64, walked as `walks` chooses; the shared walk adds its leaves to it.
void closestHit64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits, CameraWalks& walks);

// What a tile's blocks carry from one block to the next, on one BVH: the shadow packets' last
// occluder and how the camera rays walk. Default-made at a tile's start.
struct TileCarry {
    LastOccluder lastOccluder;
    CameraWalks cameraWalks;
};

// Bits 0-7: the lanes of low.lanes whose ray hits a triangle; bits 8-15: those of high.lanes.
unsigned anyHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high);

// anyHit16 that tests last's triangle and block first and leaves in `last` a triangle that
// occluded a lane.
unsigned anyHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, LastOccluder& last);

// True when closestHit16 and anyHit16 trace 16 rays at once (AVX-512F and AVX2).
bool bvhPacket16Supported();

} // namespace raylab
