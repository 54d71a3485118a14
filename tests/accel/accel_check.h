#pragma once
// Compares the BVH's answers (SIMD and scalar paths) with brute force, ray by ray.

#include "core/bvh/brute_force.h"
#include "core/bvh/bvh.h"

#include <cstring>
#include <gtest/gtest.h>
#include <vector>

namespace raylab::accel_test {

// Bit-for-bit equality of two hit records (t, u, v compared as bits, so -0 != +0 and NaN == NaN).
inline bool sameHit(const Hit& a, const Hit& b) {
    return a.triangle == b.triangle && std::memcmp(&a.t, &b.t, sizeof(float)) == 0 &&
           std::memcmp(&a.u, &b.u, sizeof(float)) == 0 &&
           std::memcmp(&a.v, &b.v, sizeof(float)) == 0;
}

// Expects closestHit, closestHitScalar, anyHit and anyHitScalar to agree with brute force on
// every ray; returns how many rays hit. Stops reporting after a few failures.
inline int expectMatchesBruteForce(const Scene& scene, const Bvh& bvh,
                                   const std::vector<Ray>& rays) {
    int hits = 0, failures = 0;
    for (std::size_t i = 0; i < rays.size() && failures < 5; ++i) {
        const Ray& ray = rays[i];
        const Hit expected = closestHitBruteForce(scene, ray);
        const Hit fast = closestHit(bvh, ray);
        const Hit scalar = closestHitScalar(bvh, ray);
        const bool expectedAny = anyHitBruteForce(scene, ray);
        const bool ok = sameHit(fast, expected) && sameHit(scalar, expected) &&
                        anyHit(bvh, ray) == expectedAny && anyHitScalar(bvh, ray) == expectedAny;
        if (!ok) {
            ++failures;
            ADD_FAILURE() << "ray " << i << ": brute force t=" << expected.t
                          << " tri=" << expected.triangle << ", closestHit t=" << fast.t
                          << " tri=" << fast.triangle << ", scalar t=" << scalar.t
                          << " tri=" << scalar.triangle << ", anyHit brute=" << expectedAny
                          << " bvh=" << anyHit(bvh, ray) << " scalar=" << anyHitScalar(bvh, ray);
        }
        hits += expected.found() ? 1 : 0;
    }
    return hits;
}

} // namespace raylab::accel_test
