#pragma once
// The 16-lane packet traversal (internal to core): two RayPackets, lanes 0-7 and 8-15, traced as
// one packet of 16 rays with AVX-512 where the CPU has it, and the entry points that let tests
// choose the path. Callers of closestHitPacket16 / anyHitPacket16 check bvhPacket16Supported()
// and that bvh.wideNodes is not empty.

#include "bvh/bvh.h"
#include "bvh/bvh_frustum.h"
#include "bvh/bvh_packet.h"
#include "ray_packet.h"

namespace raylab {

// Lanes of a 16-ray packet: bit i < 8 is lane i of the first RayPacket, bit 8 + i lane i of the
// second.
inline constexpr int kPacket16Size = 2 * kPacketSize;

// How closestHit16 / anyHit16 trace: one AVX-512 packet of 16 rays, or the two RayPackets one
// after the other through closestHit8 / anyHit8 (the path of CPUs without AVX-512).
enum class Packet16Path { Avx512, TwoPackets8 };

void closestHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, HitPacket& lowHits,
                  HitPacket& highHits, Packet16Path path);
unsigned anyHit16(const Bvh& bvh, const RayPacket& low, const RayPacket& high, Packet16Path path,
                  LastOccluder* last = nullptr);

// Traces low and high as one packet when the packets of their lanes (makePacket: the valid rays
// sharing a half's most common ray permutation) have the same permutation, else each as its own
// 8-lane packet (closestHitPacket, anyHitPacket). Every lane of lowHits and highHits is written;
// `occluded` gets the traced lanes that hit something (16 bits); with `last`, its triangle is
// tested first and a triangle that occluded a lane is left in it (LastOccluder). Returns the
// lanes left for the single-ray path (16 bits).
unsigned closestHitPacket16(const Bvh& bvh, const RayPacket& low, const RayPacket& high,
                            HitPacket& lowHits, HitPacket& highHits);
unsigned anyHitPacket16(const Bvh& bvh, const RayPacket& low, const RayPacket& high,
                        unsigned& occluded, LastOccluder* last = nullptr);

// closestHit64 (bvh_packet.h) on `path`: the AVX-512 walk of 64 rays (closestHitPacket64), or
// on the two 8-ray packets' path the AVX2 walk of eight 8-ray packets (closestHitEightPackets),
// or eight closestHit8 walks where `walks` chooses them (CameraWalks; only on that path).
void closestHit64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits, Packet16Path path,
                  CameraWalks* walks = nullptr);

// Traces the eight RayPackets rays[0, 8) as four 16-ray packets (rays[2w] lanes 0-7 and
// rays[2w + 1] lanes 8-15 of packet w, as closestHitPacket16's low and high) in one walk of the
// BVH. A pair whose halves have different permutations is traced as two 8-lane packets
// (closestHitPacket). Every lane of hits[0, 8) is written; returns the lanes left for the
// single-ray path (bit 8 k + i: lane i of rays[k]).
uint64_t closestHitPacket64(const Bvh& bvh, const RayPacket* rays, HitPacket* hits);

// closestHitCandidates and anyHitCandidates (bvh_frustum.h) of low and high at once, each
// candidate tested against the 16 lanes in one AVX-512 triangle test, when every valid lane of
// both shares one ray permutation (the common case of a block's rays); then every lane of
// lowHits and highHits is written, or `occluded` set (16 bits), as the 8-lane calls would, bit
// for bit. False otherwise, with nothing written: the caller traces each packet on its own. Call
// only where bvhPacket16Supported() and bvh.wideNodes is not empty.
bool closestHitCandidates16(const Bvh& bvh, const FrustumCandidates& candidates,
                            const RayPacket& low, const RayPacket& high, HitPacket& lowHits,
                            HitPacket& highHits);
bool anyHitCandidates16(const Bvh& bvh, const FrustumCandidates& candidates, const RayPacket& low,
                        const RayPacket& high, unsigned& occluded);

} // namespace raylab
