#pragma once
// Packets of up to 8 rays traced together through the BVH: for coherent rays (the primary rays
// of a block of pixels, the shadow rays of their hits towards one light) one traversal serves
// all of them. Every answer is exactly the single-ray one: hits[i] is closestHit(bvh, rays[i])
// bit for bit (t, u, v, triangle), occluded[i] is anyHit(bvh, rays[i]).

#include "bvh.h"
#include "ray.h"

namespace raylab {

inline constexpr int kPacketSize = 8;

// Closest hits of rays[0, count), 0 <= count <= kPacketSize, into hits[0, count).
void closestHit8(const Bvh& bvh, const Ray* rays, int count, Hit* hits);

// Any-hit answers of rays[0, count), 0 <= count <= kPacketSize, into occluded[0, count).
void anyHit8(const Bvh& bvh, const Ray* rays, int count, bool* occluded);

} // namespace raylab
