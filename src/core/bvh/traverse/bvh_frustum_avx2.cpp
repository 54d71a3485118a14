// Frustum culling with AVX2 (bvh_frustum.h). A group of rays' pyramid is bounded by four planes
// through its apex, one pair per axis of a basis (u, v) across the group's mean direction c: the
// tangents a = (w.u) / (w.c) and b = (w.v) / (w.c) of every ray's vector w lie in [a0, a1] x
// [b0, b1]. A block's image rectangle gives its pyramid from the camera's basis alone
// (frustumOfImageRect).

#include "bvh/bvh_frustum.h"
#include "bvh/bvh_packet.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh/build/bvh_collapse.h"
#include "bvh/traverse/bvh_packet_lanes.h"
#include "finite.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raylab {

namespace {

using namespace packet_lanes;

// Every ray's vector must make an angle below acos(0.2) = 78 degrees with the mean direction.
constexpr float kMinCosine = 0.2f;

RAYLAB_AVX2 inline float minOf(__m256 x) {
    __m128 m = _mm_min_ps(_mm256_castps256_ps128(x), _mm256_extractf128_ps(x, 1));
    m = _mm_min_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_min_ss(m, _mm_movehdup_ps(m)));
}

RAYLAB_AVX2 inline float maxOf(__m256 x) {
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(x), _mm256_extractf128_ps(x, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_movehdup_ps(m)));
}

RAYLAB_AVX2 inline __m256 laneMask(unsigned lanes) {
    const __m256i bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(
        _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(lanes)), bits), bits));
}

RAYLAB_AVX2 inline __m256 dot8(const __m256 a[3], const glm::vec3& b) {
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[0], _mm256_set1_ps(b.x)),
                                       _mm256_mul_ps(a[1], _mm256_set1_ps(b.y))),
                         _mm256_mul_ps(a[2], _mm256_set1_ps(b.z)));
}

// The vector w of lane i of a packet: its direction (rays from the apex) or its origin minus
// the apex (segments ending at the apex).
RAYLAB_AVX2 inline void vectorsOf(const RayPacket& rays, bool segments, const glm::vec3& apex,
                                  __m256 w[3]) {
    for (int a = 0; a < 3; ++a) {
        w[a] = segments ? _mm256_sub_ps(_mm256_load_ps(rays.origin[a]), _mm256_set1_ps(apex[a]))
                        : _mm256_load_ps(rays.direction[a]);
    }
}

glm::vec3 laneVector(const RayPacket& rays, int i, bool segments, const glm::vec3& apex) {
    const glm::vec3 o{rays.origin[0][i], rays.origin[1][i], rays.origin[2][i]};
    const glm::vec3 d{rays.direction[0][i], rays.direction[1][i], rays.direction[2][i]};
    return segments ? o - apex : d;
}

// The pyramid with its apex at `apex` over the vectors w of the packets' lanes; with
// `segments`, also the plane beyond which no w reaches (the rays end at the apex and start at
// most that far from it).
RAYLAB_AVX2 bool pyramidOf(const Bvh& bvh, const RayPacket* packets, int count,
                           const glm::vec3& apex, bool segments, RayFrustum& frustum) {
    // The axis c: any direction works (the planes come from the tangents measured against it);
    // the mean of the first and last vectors keeps the angles small.
    int first = -1, last = -1;
    for (int k = 0; k < count; ++k) {
        if (packets[k].lanes != 0) {
            last = k;
            first = first < 0 ? k : first;
        }
    }
    if (first < 0) {
        return false;
    }
    const glm::vec3 wFirst =
        laneVector(packets[first], __builtin_ctz(packets[first].lanes), segments, apex);
    const glm::vec3 wLast =
        laneVector(packets[last], 31 - __builtin_clz(packets[last].lanes), segments, apex);
    const glm::vec3 mean = glm::normalize(wFirst) + glm::normalize(wLast);
    const float meanLength = glm::length(mean);
    if (!(meanLength > 1e-3f) || !std::isfinite(meanLength)) {
        return false;
    }
    const glm::vec3 c = mean / meanLength;
    // u across c along the first packet's lanes (an image row: the pyramid then fits a block's
    // rectangle of pixels snugly), or any direction across c when that row has one lane.
    const glm::vec3 rowEnd =
        laneVector(packets[first], 31 - __builtin_clz(packets[first].lanes), segments, apex);
    glm::vec3 across = glm::normalize(rowEnd) - glm::normalize(wFirst);
    across -= glm::dot(across, c) * c;
    if (!(glm::length(across) > 1e-6f)) {
        across = glm::cross(c, std::fabs(c.x) < 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0));
    }
    const glm::vec3 u = glm::normalize(across);
    const glm::vec3 v = glm::cross(c, u);

    const __m256 inf = _mm256_set1_ps(kInfinity);
    const __m256 minusInf = _mm256_set1_ps(-kInfinity);
    const __m256 minCosineSquared = _mm256_set1_ps(kMinCosine * kMinCosine);
    __m256 a0 = inf, a1 = minusInf, b0 = inf, b1 = minusInf, far = minusInf;
    __m256 origin[3];
    for (int a = 0; a < 3; ++a) {
        origin[a] = _mm256_set1_ps(apex[a]);
    }
    for (int k = 0; k < count; ++k) {
        const RayPacket& rays = packets[k];
        if (rays.lanes == 0) {
            continue;
        }
        __m256 w[3];
        vectorsOf(rays, segments, apex, w);
        // Within acos(kMinCosine) of c (which also rules out NaN, infinite and zero vectors,
        // and huge ones whose squares overflow), and for rays, from the apex.
        const __m256 along = dot8(w, c);
        const __m256 lengthSquared =
            _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(w[0], w[0]), _mm256_mul_ps(w[1], w[1])),
                          _mm256_mul_ps(w[2], w[2]));
        __m256 ok = _mm256_and_ps(
            _mm256_cmp_ps(along, _mm256_setzero_ps(), _CMP_GT_OQ),
            _mm256_and_ps(_mm256_cmp_ps(_mm256_mul_ps(along, along),
                                        _mm256_mul_ps(lengthSquared, minCosineSquared), _CMP_GT_OQ),
                          _mm256_cmp_ps(lengthSquared, inf, _CMP_LT_OQ)));
        if (!segments) {
            for (int a = 0; a < 3; ++a) {
                ok = _mm256_and_ps(
                    ok, _mm256_cmp_ps(_mm256_load_ps(rays.origin[a]), origin[a], _CMP_EQ_OQ));
            }
        }
        if ((static_cast<unsigned>(_mm256_movemask_ps(ok)) & rays.lanes) != rays.lanes) {
            return false;
        }
        const __m256 keep = laneMask(rays.lanes);
        const __m256 inverse = _mm256_div_ps(_mm256_set1_ps(1.0f), along);
        const __m256 a = _mm256_mul_ps(dot8(w, u), inverse);
        const __m256 b = _mm256_mul_ps(dot8(w, v), inverse);
        a0 = _mm256_min_ps(a0, _mm256_blendv_ps(inf, a, keep));
        a1 = _mm256_max_ps(a1, _mm256_blendv_ps(minusInf, a, keep));
        b0 = _mm256_min_ps(b0, _mm256_blendv_ps(inf, b, keep));
        b1 = _mm256_max_ps(b1, _mm256_blendv_ps(minusInf, b, keep));
        far = _mm256_max_ps(far, _mm256_blendv_ps(minusInf, along, keep));
    }
    const float bounds[4] = {minOf(a0), maxOf(a1), minOf(b0), maxOf(b1)};
    for (float x : bounds) {
        if (!std::isfinite(x)) {
            return false;
        }
    }
    // Planes through the apex: a >= a0 is dot(u - a0 c, p - apex) >= 0, a <= a1 is
    // dot(a1 c - u, p - apex) >= 0; likewise for b.
    frustum.apex = apex;
    frustum.normal[0] = glm::normalize(u - bounds[0] * c);
    frustum.normal[1] = glm::normalize(bounds[1] * c - u);
    frustum.normal[2] = glm::normalize(v - bounds[2] * c);
    frustum.normal[3] = glm::normalize(bounds[3] * c - v);
    for (int j = 0; j < 4; ++j) {
        frustum.offset[j] = 0.0f;
    }
    frustum.planeCount = 4;
    if (segments) { // dot(c, p - apex) <= far
        frustum.normal[4] = -c;
        frustum.offset[4] = maxOf(far);
        frustum.planeCount = 5;
    }
    frustum.tolerance = frustumTolerance(bvh, apex);
    return true;
}

// The frustum's planes, broadcast.
struct PlaneRegisters {
    int count = 0;
    bool positive[kMaxFrustumPlanes][3]; // normal[j][axis] >= 0: the box's upper bound maximises
    __m256 normal[kMaxFrustumPlanes][3];
    __m256 apex[3];
    __m256 bias[kMaxFrustumPlanes]; // offset + tolerance: outside when dot + bias < 0
};

RAYLAB_AVX2 inline void loadPlanes(const RayFrustum& f, PlaneRegisters& r) {
    r.count = f.planeCount;
    for (int a = 0; a < 3; ++a) {
        r.apex[a] = _mm256_set1_ps(f.apex[a]);
    }
    for (int j = 0; j < f.planeCount; ++j) {
        for (int a = 0; a < 3; ++a) {
            r.positive[j][a] = f.normal[j][a] >= 0.0f;
            r.normal[j][a] = _mm256_set1_ps(f.normal[j][a]);
        }
        r.bias[j] = _mm256_set1_ps(f.offset[j] + f.tolerance);
    }
}

RAYLAB_AVX2 inline __m256 planeDistance(const PlaneRegisters& r, int j, __m256 x, __m256 y,
                                        __m256 z) {
    return _mm256_add_ps(
        _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(_mm256_sub_ps(x, r.apex[0]), r.normal[j][0]),
                                    _mm256_mul_ps(_mm256_sub_ps(y, r.apex[1]), r.normal[j][1])),
                      _mm256_mul_ps(_mm256_sub_ps(z, r.apex[2]), r.normal[j][2])),
        r.bias[j]);
}

// The children of node whose box is not wholly outside some plane.
RAYLAB_AVX2 inline unsigned childrenInside(const BvhWideNode& node, const PlaneRegisters& r) {
    __m256 outside = _mm256_setzero_ps();
    for (int j = 0; j < r.count; ++j) {
        __m256 corner[3];
        for (int a = 0; a < 3; ++a) {
            corner[a] = _mm256_load_ps(r.positive[j][a] ? node.upper[a] : node.lower[a]);
        }
        outside = _mm256_or_ps(outside,
                               _mm256_cmp_ps(planeDistance(r, j, corner[0], corner[1], corner[2]),
                                             _mm256_setzero_ps(), _CMP_LT_OQ));
    }
    return ~static_cast<unsigned>(_mm256_movemask_ps(outside)) & 0xffu;
}

// The triangles of a block with no plane that has all three vertices outside.
RAYLAB_AVX2 inline unsigned trianglesInside(const BvhTriangleBlock& block,
                                            const PlaneRegisters& r) {
    __m256 v[3][3];
    for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) {
            v[k][a] = _mm256_load_ps(block.vertex[k][a]);
        }
    }
    __m256 outside = _mm256_setzero_ps();
    const __m256 zero = _mm256_setzero_ps();
    for (int j = 0; j < r.count; ++j) {
        __m256 all = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
        for (int k = 0; k < 3; ++k) {
            all = _mm256_and_ps(all, _mm256_cmp_ps(planeDistance(r, j, v[k][0], v[k][1], v[k][2]),
                                                   zero, _CMP_LT_OQ));
        }
        outside = _mm256_or_ps(outside, all);
    }
    return ~static_cast<unsigned>(_mm256_movemask_ps(outside)) & 0xffu;
}

RAYLAB_AVX2 bool collectAvx2(const Bvh& bvh, const RayFrustum& frustum, FrustumCandidates& out) {
    PlaneRegisters planes;
    loadPlanes(frustum, planes);
    out.count = 0;
    uint32_t stack[kWideStackSize];
    int size = 0;
    stack[size++] = 0;
    while (size > 0) {
        const BvhWideNode& node = bvh.wideNodes[stack[--size]];
        for (unsigned m = childrenInside(node, planes); m != 0; m &= m - 1) {
            const uint32_t ref = node.child[__builtin_ctz(m)];
            if (ref == kWideEmpty) {
                continue;
            }
            if (!isLeaf(ref)) {
                stack[size++] = ref;
                continue;
            }
            const uint32_t first = firstBlock(ref);
            for (uint32_t b = first; b < first + blockCount(ref); ++b) {
                // Leaves share blocks (bvh_collapse.cpp): a block already collected is not
                // collected again.
                if (std::find(out.block, out.block + out.count, b) != out.block + out.count) {
                    continue;
                }
                const BvhTriangleBlock& block = bvh.triangleBlocks[b];
                for (unsigned t = trianglesInside(block, planes); t != 0; t &= t - 1) {
                    const int lane = __builtin_ctz(t);
                    if (repeatsFirst(block, lane)) {
                        continue;
                    }
                    if (out.count == kMaxFrustumCandidates) {
                        return false;
                    }
                    out.block[out.count] = b;
                    out.lane[out.count] = static_cast<uint8_t>(lane);
                    ++out.count;
                }
            }
        }
    }
    return true;
}

// frustumOfImageRect's pyramid, its four planes made at once (plane j in lane j: px >= x0,
// px <= x1, py >= y0, py <= y1): one square root and three divisions for all four normals. False
// when a plane has no finite, non-zero normal.
RAYLAB_AVX2 bool frameImageRect(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect,
                                RayFrustum& frustum) {
    // A ray's vector w = right (px - halfWidth) + up (halfHeight - py) + forward focal, with the
    // basis orthonormal, has dot(w, focal right - (x0 - halfWidth) forward) = focal (px - x0),
    // which is >= 0 exactly when px >= x0; likewise for the other three edges. Plane j's normal
    // is focals[j] times right (planes 0 and 1) or up (2 and 3), plus along[j] times forward.
    const float focal = camera.focal;
    const __m128 focals = _mm_setr_ps(focal, -focal, -focal, focal);
    const __m128 along = _mm_setr_ps(-(rect.x0 - camera.halfWidth), rect.x1 - camera.halfWidth,
                                     camera.halfHeight - rect.y0, -(camera.halfHeight - rect.y1));
    const __m128 infinity = _mm_set1_ps(kInfinity);
    const __m128 noSign = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
    __m128 inward[3];
    __m128 finite = _mm_castsi128_ps(_mm_set1_epi32(-1));
    for (int a = 0; a < 3; ++a) {
        const float right = camera.right[a], up = camera.up[a];
        inward[a] = _mm_add_ps(_mm_mul_ps(focals, _mm_setr_ps(right, right, up, up)),
                               _mm_mul_ps(along, _mm_set1_ps(camera.forward[a])));
        finite = _mm_and_ps(finite, _mm_cmplt_ps(_mm_and_ps(inward[a], noSign), infinity));
    }
    const __m128 length = _mm_sqrt_ps(
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(inward[0], inward[0]), _mm_mul_ps(inward[1], inward[1])),
                   _mm_mul_ps(inward[2], inward[2])));
    const __m128 ok = _mm_and_ps(
        finite, _mm_and_ps(_mm_cmpgt_ps(length, _mm_setzero_ps()), _mm_cmplt_ps(length, infinity)));
    if (_mm_movemask_ps(ok) != 0xf) {
        return false;
    }
    float normal[3][4];
    for (int a = 0; a < 3; ++a) {
        _mm_storeu_ps(normal[a], _mm_div_ps(inward[a], length));
    }
    frustum.apex = camera.origin;
    frustum.planeCount = 4;
    for (int j = 0; j < 4; ++j) {
        frustum.normal[j] = glm::vec3(normal[0][j], normal[1][j], normal[2][j]);
        frustum.offset[j] = 0.0f;
    }
    frustum.tolerance = frustumTolerance(bvh, camera.origin);
    return true;
}

// Whether no child of the root lies (partly) inside the frustum.
RAYLAB_AVX2 bool missesRoot(const Bvh& bvh, const RayFrustum& frustum) {
    PlaneRegisters r;
    loadPlanes(frustum, r);
    const BvhWideNode& root = bvh.wideNodes[0];
    for (unsigned m = childrenInside(root, r); m != 0; m &= m - 1) {
        if (root.child[__builtin_ctz(m)] != kWideEmpty) {
            return false;
        }
    }
    return true;
}

} // namespace

bool frustumOfImageRect(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect,
                        RayFrustum& frustum) {
    static const bool simd = bvhSimdSupported();
    return simd && !bvh.wideNodes.empty() && isFinite(camera.origin) && rect.x0 <= rect.x1 &&
           rect.y0 <= rect.y1 && frameImageRect(bvh, camera, rect, frustum);
}

bool frustumOfRays(const Bvh& bvh, const RayPacket* packets, int count, RayFrustum& frustum) {
    static const bool simd = bvhSimdSupported();
    if (!simd || bvh.wideNodes.empty() || count <= 0 || count > kPacketSize) {
        return false;
    }
    int first = 0;
    while (first < count && packets[first].lanes == 0) {
        ++first;
    }
    if (first == count) {
        return false;
    }
    const RayPacket& rays = packets[first];
    const int lane = __builtin_ctz(rays.lanes);
    const glm::vec3 origin{rays.origin[0][lane], rays.origin[1][lane], rays.origin[2][lane]};
    return pyramidOf(bvh, packets, count, origin, false, frustum);
}

bool frustumOfSegments(const Bvh& bvh, const RayPacket* packets, int count, const glm::vec3& end,
                       RayFrustum& frustum) {
    static const bool simd = bvhSimdSupported();
    if (!simd || bvh.wideNodes.empty() || count <= 0 || count > kPacketSize) {
        return false;
    }
    return pyramidOf(bvh, packets, count, end, true, frustum);
}

bool imageRectMissesScene(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect) {
    RayFrustum frustum;
    return frustumOfImageRect(bvh, camera, rect, frustum) && missesRoot(bvh, frustum);
}

bool frustumCandidates(const Bvh& bvh, const RayFrustum& frustum, FrustumCandidates& candidates) {
    candidates.count = 0;
    return !bvh.wideNodes.empty() && collectAvx2(bvh, frustum, candidates);
}

RAYLAB_AVX2 void closestHitCandidates(const Bvh& bvh, const FrustumCandidates& candidates,
                                      const RayPacket& rays, HitPacket& hits) {
    if (bvh.wideNodes.empty()) {
        closestHit8(bvh, rays, hits);
        return;
    }
    PacketRays p;
    makePacket(rays, p);
    if (p.lanes != 0) {
        PacketBest best = noHitYet();
        for (int i = 0; i < candidates.count; ++i) {
            keepTriangle(best, bvh.triangleBlocks[candidates.block[i]], candidates.lane[i], p, rays,
                         p.lanes);
        }
        writeBest(best, p.lanes, hits);
    } else {
        hits.clear();
    }
    for (unsigned m = p.others; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        hits.set(i, closestHit(bvh, rays.ray(i)));
    }
}

RAYLAB_AVX2 unsigned anyHitCandidates(const Bvh& bvh, const FrustumCandidates& candidates,
                                      const RayPacket& rays) {
    if (bvh.wideNodes.empty()) {
        return anyHit8(bvh, rays);
    }
    PacketRays p;
    makePacket(rays, p);
    unsigned open = p.lanes;
    for (int i = 0; i < candidates.count && open != 0; ++i) {
        open &=
            ~hitLanes(bvh.triangleBlocks[candidates.block[i]], candidates.lane[i], p, rays, open);
    }
    unsigned occluded = p.lanes & ~open;
    for (unsigned m = p.others; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        if (anyHit(bvh, rays.ray(i))) {
            occluded |= 1u << i;
        }
    }
    return occluded;
}

} // namespace raylab

#else // not x86: no 8-wide BVH is built, so there is never a frustum.

namespace raylab {
bool frustumOfRays(const Bvh&, const RayPacket*, int, RayFrustum&) { return false; }
bool frustumOfImageRect(const Bvh&, const PrimaryRays&, const ImageRect&, RayFrustum&) {
    return false;
}
bool imageRectMissesScene(const Bvh&, const PrimaryRays&, const ImageRect&) { return false; }
bool frustumOfSegments(const Bvh&, const RayPacket*, int, const glm::vec3&, RayFrustum&) {
    return false;
}
bool frustumCandidates(const Bvh&, const RayFrustum&, FrustumCandidates& candidates) {
    candidates.count = 0;
    return false;
}
void closestHitCandidates(const Bvh& bvh, const FrustumCandidates&, const RayPacket& rays,
                          HitPacket& hits) {
    closestHit8(bvh, rays, hits);
}
unsigned anyHitCandidates(const Bvh& bvh, const FrustumCandidates&, const RayPacket& rays) {
    return anyHit8(bvh, rays);
}
} // namespace raylab

#endif
