#pragma once
// Per-ray constants of the slab test against node boxes (internal to core), shared by the
// scalar and the SIMD traversal so both cull the same way.
//
// The test is conservative: it may keep a box the exact ray misses, never drop one it hits.
// Direction components of +-0 (and tiny ones) become +-1e-30, so 1/d stays finite and no
// 0 * inf NaN appears; the far distances are scaled up by kBoxRoundUp to cover the rounding of
// the slab distances and of the triangle test's t (ties at equal t must still be found). A ray
// that knows its near and far planes (the single-ray tests) scales 1/d and the limit rather
// than the far distance: the product then leaves the chain of dependent operations between a
// node's load and its children's mask, which bounds a single ray walked alone (3-4% less time a
// bounce ray: PERFORMANCE.md, "What each change gained: single rays and bounce rays"). The packets
// take both planes' distances for either sign and scale the far one.

#include "ray.h"

#include <cmath>

namespace raylab {

inline constexpr float kBoxRoundUp = 1.0f + 0x1p-18f;

// The direction component the slab test divides by: d, or +-1e-30 when |d| is smaller.
inline float boxDirection(float d) { return std::fabs(d) < 1e-30f ? std::copysign(1e-30f, d) : d; }

struct BoxRay {
    float origin[3];
    float inverse[3];    // 1 / direction, finite: the near planes' distances
    float farInverse[3]; // inverse * kBoxRoundUp: the far planes' distances, scaled up
    int nearOffset[3];   // 0 when the ray runs towards +axis (the near plane is the lower bound)
    float tMin;

    explicit BoxRay(const Ray& ray) : tMin(ray.tMin) {
        for (int a = 0; a < 3; ++a) {
            origin[a] = ray.origin[a];
            inverse[a] = 1.0f / boxDirection(ray.direction[a]);
            farInverse[a] = inverse[a] * kBoxRoundUp;
            nearOffset[a] = inverse[a] >= 0.0f ? 0 : 1;
        }
    }
};

// Slab test of one box given as {lower, upper} per axis. Returns true and the entry distance
// when the box overlaps (tMin, limit] on the ray (limit scaled up as the far distances are).
inline bool hitBox(const BoxRay& r, const float (&bounds)[2][3], float limit, float& tNear) {
    float tn = r.tMin, tf = limit * kBoxRoundUp;
    for (int a = 0; a < 3; ++a) {
        const float t0 = (bounds[r.nearOffset[a]][a] - r.origin[a]) * r.inverse[a];
        const float t1 = (bounds[1 - r.nearOffset[a]][a] - r.origin[a]) * r.farInverse[a];
        tn = t0 > tn ? t0 : tn;
        tf = t1 < tf ? t1 : tf;
    }
    tNear = tn;
    return tn <= tf;
}

} // namespace raylab
