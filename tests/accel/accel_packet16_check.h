#pragma once
// Checks of 16-ray packets (closestHit16, anyHit16) against single rays, the scalar reference
// and brute force, lane by lane, bit for bit.

#include "core/bvh/bvh.h"
#include "core/bvh/traverse/bvh_packet16_traverse.h"
#include "core/ray.h"
#include "core/scene.h"

#include <vector>

namespace raylab::accel_test {

// The paths this CPU can run: the two 8-ray packets always, the AVX-512 packet where it has it.
std::vector<Packet16Path> packet16Paths();

// Traces rays[0, count) (count <= 16) on `path` as one packet of 16 (lanes 0-7 low, 8-15 high)
// with only the lanes of `mask` set, and expects each of those lanes to equal the single ray's
// closestHit, closestHitScalar, anyHit and anyHitScalar (and brute force when `scene` is given),
// and every other lane to hold no hit. With `last`, the any-hit answers again with that
// LastOccluder (tested first, then updated) must be the same. Returns how many lanes hit; adds
// failures to `failures`.
int expectPacket16(const Bvh& bvh, const Ray* rays, int count, unsigned mask, Packet16Path path,
                   const Scene* scene, int& failures, LastOccluder* last = nullptr);

// All of `rays` in packets of `size` consecutive rays (the last one partial) on `path`, with one
// LastOccluder carried from each packet to the next.
int expectPackets16(const Bvh& bvh, const std::vector<Ray>& rays, Packet16Path path,
                    const Scene* scene = nullptr, int size = kPacket16Size);

} // namespace raylab::accel_test
