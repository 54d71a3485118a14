#pragma once
// A packet's frustum and its tests of 8 boxes at once, shared by the packet traversals of 8, 16
// and 64 rays (internal to core; only files that run on CPUs with AVX2 may include it): the
// frustum of 8 lanes (makeFrustum8; the 16-ray one is made in bvh_packet16_parts.h), the test of
// a node's 8 children or of a block's 8 triangle boxes against it (frustumBoxes,
// frustumTriangles), and one lane's own test of a node's 8 children (laneChildren).
//
// Every test here keeps a superset of what the lanes' own slab tests keep (hitChild), so a
// traversal that culls by them finds the same answers, bit for bit.

#include "bvh/bvh.h"
#include "bvh/traverse/bvh_box_ray.h"
#include "bvh/traverse/bvh_packet_setup.h"

namespace raylab::packet_lanes {

// Bounds of a packet's box test, for all 8 children of a node at once: per axis, the interval
// of the lanes' origins and of their inverse directions, so that for every lane
// (bound - origin) * inverse lies within [min, max] of the products at the intervals' ends
// (float subtraction and multiplication round monotonically). Valid when, per axis, every lane's
// inverse has one sign: then the near bound is the same plane of the box for all of them.
struct Frustum {
    bool valid = false;
    int nearOffset[3], farOffset[3];    // into BvhWideNode's floats, as in bvh_traverse_avx2.cpp
    __m256 nearOrigin[3], farOrigin[3]; // the origins that make (bound - origin) smallest, largest
    __m256 inverseMin[3], inverseMax[3];
    __m256 tMin; // the lanes' smallest tMin
};

// x with each lane outside `lanes` (not 0) replaced by the first lane of `lanes`.
RAYLAB_AVX2 inline __m256 activeLanesOnly(__m256 x, unsigned lanes) {
    const __m256i bits = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    const __m256i in = _mm256_cmpeq_epi32(
        _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(lanes)), bits), bits);
    const __m256 first = _mm256_permutevar8x32_ps(x, _mm256_set1_epi32(__builtin_ctz(lanes)));
    return _mm256_blendv_ps(first, x, _mm256_castsi256_ps(in));
}

// The largest (`largest`) or the smallest of x and y, lane by lane.
template <bool largest> RAYLAB_AVX2 inline __m256 extreme(__m256 x, __m256 y) {
    if constexpr (largest) {
        return _mm256_max_ps(x, y);
    } else {
        return _mm256_min_ps(x, y);
    }
}

// The largest (`largest`) or the smallest of x's lanes of `lanes` (not 0). With all 8 lanes, as
// most packets have, no lane is replaced first (PERFORMANCE.md, "A packet's set-up made lighter").
template <bool largest> RAYLAB_AVX2 inline float laneExtreme(__m256 x, unsigned lanes) {
    __m256 m = lanes == 0xffu ? x : activeLanesOnly(x, lanes);
    m = extreme<largest>(m, _mm256_permute2f128_ps(m, m, 1));
    m = extreme<largest>(m, _mm256_shuffle_ps(m, m, 0x4e));
    m = extreme<largest>(m, _mm256_shuffle_ps(m, m, 0xb1));
    return _mm256_cvtss_f32(m);
}

RAYLAB_AVX2 inline float laneMin(__m256 x, unsigned lanes) { return laneExtreme<false>(x, lanes); }
RAYLAB_AVX2 inline float laneMax(__m256 x, unsigned lanes) { return laneExtreme<true>(x, lanes); }

// The frustum of the lanes of p.lanes (valid only when there are any, and per axis their inverse
// directions share one sign).
RAYLAB_AVX2 inline void makeFrustum8(const PacketRays& p, Frustum& f) {
    f.valid = p.lanes != 0;
    const __m256 zero = _mm256_setzero_ps();
    for (int a = 0; a < 3 && f.valid; ++a) {
        const unsigned negative = p.lanes & static_cast<unsigned>(_mm256_movemask_ps(
                                                _mm256_cmp_ps(p.inverse[a], zero, _CMP_LT_OQ)));
        f.valid = negative == 0 || negative == p.lanes;
        const int nearIsUpper = negative != 0 ? 1 : 0;
        // lower[a] starts at float a * 8, upper[a] at 24 + a * 8.
        f.nearOffset[a] = nearIsUpper * 24 + a * kWideLanes;
        f.farOffset[a] = (1 - nearIsUpper) * 24 + a * kWideLanes;
        const float originMin = laneMin(p.origin[a], p.lanes);
        const float originMax = laneMax(p.origin[a], p.lanes);
        // Towards +a the near distance is smallest from the largest origin, the far distance
        // largest from the smallest one; towards -a the other way round.
        f.nearOrigin[a] = _mm256_set1_ps(nearIsUpper != 0 ? originMin : originMax);
        f.farOrigin[a] = _mm256_set1_ps(nearIsUpper != 0 ? originMax : originMin);
        f.inverseMin[a] = _mm256_set1_ps(laneMin(p.inverse[a], p.lanes));
        f.inverseMax[a] = _mm256_set1_ps(laneMax(p.inverse[a], p.lanes));
    }
    f.tMin = _mm256_set1_ps(f.valid ? laneMin(p.tMin, p.lanes) : 0.0f);
}

// Widens f to bound also the lanes g bounds (both valid): false, f unusable, when their inverse
// directions differ in sign on an axis (then no frustum of this form bounds both).
RAYLAB_AVX2 inline bool joinFrustum(Frustum& f, const Frustum& g) {
    for (int a = 0; a < 3; ++a) {
        if (g.nearOffset[a] != f.nearOffset[a]) {
            return false;
        }
        // As makeFrustum8: towards -a (near bound upper) the near origin is the smallest.
        const bool nearIsUpper = f.nearOffset[a] >= 3 * kWideLanes;
        f.nearOrigin[a] = nearIsUpper ? _mm256_min_ps(f.nearOrigin[a], g.nearOrigin[a])
                                      : _mm256_max_ps(f.nearOrigin[a], g.nearOrigin[a]);
        f.farOrigin[a] = nearIsUpper ? _mm256_max_ps(f.farOrigin[a], g.farOrigin[a])
                                     : _mm256_min_ps(f.farOrigin[a], g.farOrigin[a]);
        f.inverseMin[a] = _mm256_min_ps(f.inverseMin[a], g.inverseMin[a]);
        f.inverseMax[a] = _mm256_max_ps(f.inverseMax[a], g.inverseMax[a]);
    }
    f.tMin = _mm256_min_ps(f.tMin, g.tMin);
    return true;
}

// The frustum of several packets' lanes, frustums[k] being packet k's (nullptr for a packet
// without lanes): each bounds its packet's lanes, so their joined intervals bound all of them.
// Invalid when a packet's is, when two packets' inverse directions differ in sign on an axis, or
// when no packet has lanes.
RAYLAB_AVX2 inline Frustum joinFrustums(const Frustum* const* frustums, int count) {
    Frustum f;
    bool any = false;
    for (int k = 0; k < count; ++k) {
        const Frustum* g = frustums[k];
        if (g == nullptr) {
            continue;
        }
        if (!g->valid) {
            return Frustum{};
        }
        if (!any) {
            f = *g;
            any = true;
        } else if (!joinFrustum(f, *g)) {
            return Frustum{};
        }
    }
    f.valid = any;
    return f;
}

// Of 8 boxes given as lower[3][8] then upper[3][8] floats (BvhWideNode's layout), those some
// lane may enter before `limitMax` (the lanes' largest limit): a superset of the boxes any lane's
// own slab test keeps (hitChild), since each lane's near distance is at least the frustum's and
// its far distance at most the frustum's. Also their frustum near distances.
RAYLAB_AVX2 inline unsigned frustumBoxes(const float* bounds, const Frustum& f, float limitMax,
                                         __m256& tNear) {
    __m256 tn = f.tMin, tf = _mm256_set1_ps(limitMax);
    for (int a = 0; a < 3; ++a) {
        const __m256 xn = _mm256_sub_ps(_mm256_load_ps(bounds + f.nearOffset[a]), f.nearOrigin[a]);
        const __m256 xf = _mm256_sub_ps(_mm256_load_ps(bounds + f.farOffset[a]), f.farOrigin[a]);
        tn = _mm256_max_ps(tn, _mm256_min_ps(_mm256_mul_ps(xn, f.inverseMin[a]),
                                             _mm256_mul_ps(xn, f.inverseMax[a])));
        tf = _mm256_min_ps(tf, _mm256_max_ps(_mm256_mul_ps(xf, f.inverseMin[a]),
                                             _mm256_mul_ps(xf, f.inverseMax[a])));
    }
    tNear = tn;
    return static_cast<unsigned>(_mm256_movemask_ps(
        _mm256_cmp_ps(tn, _mm256_mul_ps(tf, _mm256_set1_ps(kBoxRoundUp)), _CMP_LE_OQ)));
}

// The bounding boxes of a block's 8 triangles, each widened by `pad` (Bvh::boxPad) as every node
// box is, in BvhWideNode's layout (lower[3][8] then upper[3][8]) for frustumBoxes.
struct alignas(32) TriangleBounds {
    float bounds[2][3][kWideLanes];
};

RAYLAB_AVX2 inline TriangleBounds triangleBounds(const BvhTriangleBlock& block, float pad) {
    TriangleBounds b;
    for (int a = 0; a < 3; ++a) {
        const __m256 v0 = _mm256_load_ps(block.vertex[0][a]);
        const __m256 v1 = _mm256_load_ps(block.vertex[1][a]);
        const __m256 v2 = _mm256_load_ps(block.vertex[2][a]);
        const __m256 widen = _mm256_set1_ps(pad);
        _mm256_store_ps(b.bounds[0][a],
                        _mm256_sub_ps(_mm256_min_ps(_mm256_min_ps(v0, v1), v2), widen));
        _mm256_store_ps(b.bounds[1][a],
                        _mm256_add_ps(_mm256_max_ps(_mm256_max_ps(v0, v1), v2), widen));
    }
    return b;
}

// The triangles of a block that some lane may hit before `limitMax`, given the block's widened
// triangle boxes `b` (triangleBounds): those whose box passes frustumBoxes (a ray the watertight
// test finds on a triangle enters that box, as it enters every node box holding the triangle);
// all 8 without a valid frustum.
RAYLAB_AVX2 inline unsigned frustumTriangles(const TriangleBounds& b, const Frustum& f,
                                             float limitMax) {
    if (!f.valid) {
        return 0xffu;
    }
    __m256 tNear;
    return frustumBoxes(&b.bounds[0][0][0], f, limitMax, tNear);
}

// The same, the boxes made from `block` widened by `pad`.
RAYLAB_AVX2 inline unsigned frustumTriangles(const BvhTriangleBlock& block, float pad,
                                             const Frustum& f, float limitMax) {
    return f.valid ? frustumTriangles(triangleBounds(block, pad), f, limitMax) : 0xffu;
}

// The children one lane's ray enters before `limit` (bvh_traverse_avx2.cpp's hitChildren for
// that one ray, with plain min and max of the two planes so that it holds for either sign): the
// lane's origin, inverse direction (1 / boxDirection) and tMin as floats.
RAYLAB_AVX2 inline unsigned laneChildren(const BvhWideNode& node, const float origin[3],
                                         const float inverse[3], float tMin, float limit) {
    __m256 tn = _mm256_set1_ps(tMin), tf = _mm256_set1_ps(limit);
    for (int a = 0; a < 3; ++a) {
        const __m256 o = _mm256_set1_ps(origin[a]);
        const __m256 inv = _mm256_set1_ps(inverse[a]);
        const __m256 t0 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.lower[a]), o), inv);
        const __m256 t1 = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(node.upper[a]), o), inv);
        tn = _mm256_max_ps(tn, _mm256_min_ps(t0, t1));
        tf = _mm256_min_ps(tf, _mm256_max_ps(t0, t1));
    }
    return static_cast<unsigned>(_mm256_movemask_ps(
        _mm256_cmp_ps(tn, _mm256_mul_ps(tf, _mm256_set1_ps(kBoxRoundUp)), _CMP_LE_OQ)));
}

} // namespace raylab::packet_lanes
