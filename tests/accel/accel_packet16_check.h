#pragma once
// Checks of 16-ray packets (closestHit16, anyHit16) and of 64-ray packets (closestHit64)
// against single rays, the scalar reference and brute force, lane by lane, bit for bit.

#include "core/bvh/bvh.h"
#include "core/bvh/traverse/bvh_packet16_traverse.h"
#include "core/ray.h"
#include "core/scene.h"

#include <cstdint>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace raylab::accel_test {

// A path's name in the tests' names: Avx512, TwoPackets8.
std::string packet16PathName(const ::testing::TestParamInfo<Packet16Path>& path);

// The paths this CPU can run: the two 8-ray packets always, the AVX-512 packet where it has it.
std::vector<Packet16Path> packet16Paths();

// True when the triangle `last` names (one of bvh's blocks and slots) is hit within its range by
// the ray of some lane of `lanes` (lane i's ray is rays[i]).
bool rememberedTriangleHit(const Bvh& bvh, const LastOccluder& last, const Ray* rays,
                           unsigned lanes);

// Traces rays[0, count) (count <= 16) on `path` as one packet of 16 (lanes 0-7 low, 8-15 high)
// with only the lanes of `mask` set, and expects each of those lanes to equal the single ray's
// closestHit, closestHitScalar, anyHit and anyHitScalar (and brute force when `scene` is given),
// and every other lane to hold no hit. With `last`, the any-hit answers again with that
// LastOccluder (its triangle and block tested first, then updated) must be the same, and a
// triangle it names anew must be one an occluded lane's ray hits. Returns how many lanes hit; adds
// failures to `failures`.
int expectPacket16(const Bvh& bvh, const Ray* rays, int count, unsigned mask, Packet16Path path,
                   const Scene* scene, int& failures, LastOccluder* last = nullptr);

// All of `rays` in packets of `size` consecutive rays (the last one partial) on `path`, with one
// LastOccluder carried from each packet to the next.
int expectPackets16(const Bvh& bvh, const std::vector<Ray>& rays, Packet16Path path,
                    const Scene* scene = nullptr, int size = kPacket16Size);

// Traces rays[0, count) (count <= 64; ray 8 k + i as lane i of packet k) on `path` with
// closestHit64, only the lanes of `mask` set, and expects each of those lanes to equal the single
// ray's closestHit and closestHitScalar (and brute force when `scene` is given), and every other
// lane to hold no hit. Returns how many lanes hit; adds failures to `failures`.
int expectPacket64(const Bvh& bvh, const Ray* rays, int count, uint64_t mask, Packet16Path path,
                   const Scene* scene, int& failures);

// All of `rays` in packets of 64 consecutive rays (the last one partial) on `path`.
int expectPackets64(const Bvh& bvh, const std::vector<Ray>& rays, Packet16Path path,
                    const Scene* scene = nullptr);

} // namespace raylab::accel_test
