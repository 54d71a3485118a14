#pragma once
// One ray against the 8 triangles of a BvhTriangleBlock at once (internal to core; only files
// that run on CPUs with AVX2 may include it): the single-ray traversal's leaf test
// (bvh_traverse_avx2.cpp), which the 8- and 16-ray packets also use, lane by lane, for a block
// that few of their lanes reach (bvh_packet_avx2.cpp, bvh_packet16_avx512.cpp). And one triangle
// of a block through the scalar test, for the lanes watertight_avx2.h leaves to it.

#include "bvh/bvh_wide.h"
#include "triangle_intersection.h"
#include "watertight_avx2.h"

namespace raylab {

// A ray's triangle-test constants (WatertightRay's), each broadcast to 8 lanes: the origin in
// permuted order kx, ky, kz, the offsets of those axes in a block's vertex floats, the shear, and
// the ray's interval.
struct BlockRay {
    __m256 originK[3];
    int vertexOffset[3];
    __m256 shearX, shearY, shearZ, tMin, tMax;
};

// The watertight test of the block's 8 triangles (lane i: triangle i) against the ray.
RAYLAB_AVX2 inline LaneHits intersectBlock(const BvhTriangleBlock& block, const BlockRay& r) {
    const float* v = &block.vertex[0][0][0];
    __m256 x[3], y[3], z[3]; // sheared a, b, c; z is a[kz] etc. before scaling
    for (int k = 0; k < 3; ++k) {
        const float* p = v + k * 3 * kWideLanes;
        const __m256 dx = _mm256_sub_ps(_mm256_load_ps(p + r.vertexOffset[0]), r.originK[0]);
        const __m256 dy = _mm256_sub_ps(_mm256_load_ps(p + r.vertexOffset[1]), r.originK[1]);
        z[k] = _mm256_sub_ps(_mm256_load_ps(p + r.vertexOffset[2]), r.originK[2]);
        x[k] = _mm256_sub_ps(dx, _mm256_mul_ps(r.shearX, z[k]));
        y[k] = _mm256_sub_ps(dy, _mm256_mul_ps(r.shearY, z[k]));
    }
    return watertightLanes(x, y, z, r.shearZ, r.tMin, r.tMax);
}

// Triangle `tri` of a block through the scalar test (intersectTriangle), for `ray`: the lanes
// whose edge function is exactly zero.
inline bool intersectLane(const BvhTriangleBlock& block, int tri, const Ray& ray, float& t,
                          float& u, float& v) {
    glm::vec3 q[3];
    for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) {
            q[k][a] = block.vertex[k][a][tri];
        }
    }
    return intersectTriangle(WatertightRay(ray), q[0], q[1], q[2], t, u, v);
}

// One ray's closest hit so far, as the packets keep it per lane: (t, triangle index) decides;
// u and v are held as e1 and e2 until divided by det (det = 1 when they are final).
struct LaneBest {
    float t;
    uint32_t triangle;
    float e1, e2, det;
};

// Keeps in `best` each hit of h (intersectBlock of `block` for `ray`) that is closer by the
// (t, triangle index) rule, the lanes of h.exact through intersectLane. Returns whether best
// changed.
RAYLAB_AVX2 inline bool keepBlockHits(LaneBest& best, const BvhTriangleBlock& block,
                                      const LaneHits& h, const Ray& ray) {
    bool closer = false;
    if (h.hits != 0) {
        alignas(32) float t[kWideLanes], e1[kWideLanes], e2[kWideLanes], det[kWideLanes];
        _mm256_store_ps(t, h.t);
        _mm256_store_ps(e1, h.e1);
        _mm256_store_ps(e2, h.e2);
        _mm256_store_ps(det, h.det);
        for (unsigned m = h.hits; m != 0; m &= m - 1) {
            const int tri = __builtin_ctz(m);
            const uint32_t index = block.sceneIndex[tri];
            if (closerHit(t[tri], index, best.t, best.triangle)) {
                best = LaneBest{t[tri], index, e1[tri], e2[tri], det[tri]};
                closer = true;
            }
        }
    }
    for (unsigned m = h.exact; m != 0; m &= m - 1) {
        const int tri = __builtin_ctz(m);
        const uint32_t index = block.sceneIndex[tri];
        float t, u, v;
        if (intersectLane(block, tri, ray, t, u, v) && closerHit(t, index, best.t, best.triangle)) {
            best = LaneBest{t, index, u, v, 1.0f};
            closer = true;
        }
    }
    return closer;
}

// The slot of a triangle that h (intersectBlock of `block` for `ray`) holds a hit on, the lanes
// of h.exact through intersectLane; -1 when it holds none.
inline int blockHitSlot(const BvhTriangleBlock& block, const LaneHits& h, const Ray& ray) {
    if (h.hits != 0) {
        return __builtin_ctz(h.hits);
    }
    for (unsigned m = h.exact; m != 0; m &= m - 1) {
        float t, u, v;
        if (intersectLane(block, __builtin_ctz(m), ray, t, u, v)) {
            return __builtin_ctz(m);
        }
    }
    return -1;
}

// Whether h (intersectBlock of `block` for `ray`) holds a hit.
inline bool blockHit(const BvhTriangleBlock& block, const LaneHits& h, const Ray& ray) {
    return blockHitSlot(block, h, ray) >= 0;
}

} // namespace raylab
