// AVX2 packet traversal of the 8-wide BVH: the 8 lanes of a register are 8 rays. A node tests
// each child's box against all rays and descends when any active ray hits it; a leaf tests each
// triangle against all rays at once.
//
// Exactness, lane by lane: the triangle test is intersectTriangle (triangle_intersection.cpp)
// operation for operation (core builds with -ffp-contract=off), valid because all lanes share
// the ray permutation kx, ky, kz (bvh_packet.cpp sends the others to the single-ray path); lanes
// with an edge function of exactly zero go to intersectTriangle itself. A lane keeps the minimum
// of (t, triangle index) over the triangles it hits, and only drops boxes that start beyond its
// own closest hit, as the single-ray traversal does, so the visiting order (the packet's) does
// not change its answer.

#include "bvh_packet_traverse.h"

#if defined(__x86_64__) || defined(__i386__)

#include "bvh_collapse.h"
#include "bvh_packet_setup.h"
#include "triangle_intersection.h"

namespace raylab {

namespace {

// Slab test of child c's box against every lane (bvh_box_ray.h's hitBox per lane: the near
// plane is the smaller of the two distances). Returns the lanes whose (tMin, limit] overlaps the
// box, and their entry distances.
RAYLAB_AVX2 inline unsigned hitChild(const BvhWideNode& node, int c, const PacketRays& p,
                                     __m256 limit, __m256& tNear) {
    __m256 tn = p.tMin, tf = limit;
    for (int a = 0; a < 3; ++a) {
        const __m256 t0 = _mm256_mul_ps(
            _mm256_sub_ps(_mm256_set1_ps(node.lower[a][c]), p.origin[a]), p.inverse[a]);
        const __m256 t1 = _mm256_mul_ps(
            _mm256_sub_ps(_mm256_set1_ps(node.upper[a][c]), p.origin[a]), p.inverse[a]);
        tn = _mm256_max_ps(tn, _mm256_min_ps(t0, t1));
        tf = _mm256_min_ps(tf, _mm256_max_ps(t0, t1));
    }
    tNear = tn;
    return static_cast<unsigned>(_mm256_movemask_ps(
        _mm256_cmp_ps(tn, _mm256_mul_ps(tf, _mm256_set1_ps(kBoxRoundUp)), _CMP_LE_OQ)));
}

// Triangle `tri` of a block against every lane (watertight_avx2.h).
RAYLAB_AVX2 inline LaneHits intersectTriangle8(const BvhTriangleBlock& block, int tri,
                                               const PacketRays& p) {
    const float* v = &block.vertex[0][0][tri];
    __m256 x[3], y[3], z[3]; // sheared a, b, c; z is a[kz] etc. before scaling
    for (int k = 0; k < 3; ++k) {
        const float* q = v + k * 3 * kWideLanes;
        const __m256 dx = _mm256_sub_ps(_mm256_set1_ps(q[p.vertexOffset[0]]), p.originK[0]);
        const __m256 dy = _mm256_sub_ps(_mm256_set1_ps(q[p.vertexOffset[1]]), p.originK[1]);
        z[k] = _mm256_sub_ps(_mm256_set1_ps(q[p.vertexOffset[2]]), p.originK[2]);
        x[k] = _mm256_sub_ps(dx, _mm256_mul_ps(p.shearX, z[k]));
        y[k] = _mm256_sub_ps(dy, _mm256_mul_ps(p.shearY, z[k]));
    }
    return watertightLanes(x, y, z, p.shearZ, p.tMin, p.tMax);
}

// A block's triangle through the scalar test, for one lane's ray.
bool intersectLane(const BvhTriangleBlock& block, int tri, const Ray& ray, float& t, float& u,
                   float& v) {
    glm::vec3 q[3];
    for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 3; ++a) {
            q[k][a] = block.vertex[k][a][tri];
        }
    }
    return intersectTriangle(WatertightRay(ray), q[0], q[1], q[2], t, u, v);
}

// Spare lanes of a block repeat its first triangle (bvh_wide.h); pre-split copies of one
// triangle have equal vertices too. Either way testing it again cannot change an answer.
inline bool repeatsFirst(const BvhTriangleBlock& block, int tri) {
    return tri > 0 && block.sceneIndex[tri] == block.sceneIndex[0];
}

inline bool isLeaf(uint32_t ref) { return (ref & kWideLeafFlag) != 0; }
inline uint32_t firstBlock(uint32_t ref) { return ref & kWideFirstBlockMask; }
inline uint32_t blockCount(uint32_t ref) { return ((ref & ~kWideLeafFlag) >> kWideBlockShift) + 1; }

struct PacketEntry {
    __m256 tNear; // per lane
    uint32_t ref;
    unsigned lanes; // lanes whose ray entered the box
};

// The children of a node that some lane of `active` hits, sorted nearest last by the entry
// distance of their first hitting lane when `ordered` (closest hit), else in slot order (any
// hit: the sort costs more than it saves there; callgrind on the shadow packets: box -3.6%,
// Sponza -3.6%, dragon -8.7% instructions without it). Returns how many.
template <bool ordered>
RAYLAB_AVX2 inline int hitChildren(const BvhWideNode& node, const PacketRays& p, __m256 limit,
                                   unsigned active, PacketEntry* out) {
    int n = 0;
    float key[kWideLanes];
    for (int c = 0; c < kWideLanes; ++c) {
        if (node.child[c] == kWideEmpty) {
            continue;
        }
        __m256 tNear;
        const unsigned lanes = hitChild(node, c, p, limit, tNear) & active;
        if (lanes == 0) {
            continue;
        }
        if constexpr (!ordered) {
            out[n++] = PacketEntry{tNear, node.child[c], lanes};
            continue;
        }
        alignas(32) float t[kWideLanes];
        _mm256_store_ps(t, tNear);
        const float k = t[__builtin_ctz(lanes)];
        int i = n++;
        for (; i > 0 && key[i - 1] < k; --i) {
            key[i] = key[i - 1];
            out[i] = out[i - 1];
        }
        key[i] = k;
        out[i] = PacketEntry{tNear, node.child[c], lanes};
    }
    return n;
}

// Goes on with the last of a node's n > 0 hit children (the nearest, when they are sorted) and
// its lanes, and pushes the others on the stack.
RAYLAB_AVX2 inline void descend(const PacketEntry* children, int n, PacketEntry* stack, int& size,
                                uint32_t& ref, unsigned& active) {
    for (int i = 0; i < n - 1; ++i) {
        stack[size++] = children[i];
    }
    ref = children[n - 1].ref;
    active = children[n - 1].lanes;
}

// The closest hit per lane so far: (t, triangle) decides; u and v are held as e1 and e2 until
// divided by det at the end (det = 1 for hits from intersectTriangle, whose u, v are final).
struct PacketBest {
    __m256 t, e1, e2, det;
    __m256i triangle;
};

RAYLAB_AVX2 inline void keepCloser(PacketBest& best, const LaneHits& h, unsigned lanes,
                                   uint32_t index) {
    // Unsigned index < best.triangle: compare with the sign bits flipped.
    const __m256i flip = _mm256_set1_epi32(static_cast<int>(0x80000000u));
    const __m256i lower =
        _mm256_cmpgt_epi32(_mm256_xor_si256(best.triangle, flip),
                           _mm256_set1_epi32(static_cast<int>(index ^ 0x80000000u)));
    const __m256 closer = _mm256_or_ps(
        _mm256_cmp_ps(h.t, best.t, _CMP_LT_OQ),
        _mm256_and_ps(_mm256_cmp_ps(h.t, best.t, _CMP_EQ_OQ), _mm256_castsi256_ps(lower)));
    const unsigned better = lanes & static_cast<unsigned>(_mm256_movemask_ps(closer));
    if (better == 0) {
        return;
    }
    const __m256i bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    const __m256 mask = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
        _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(better)), bits), bits));
    best.t = _mm256_blendv_ps(best.t, h.t, mask);
    best.e1 = _mm256_blendv_ps(best.e1, h.e1, mask);
    best.e2 = _mm256_blendv_ps(best.e2, h.e2, mask);
    best.det = _mm256_blendv_ps(best.det, h.det, mask);
    best.triangle = _mm256_blendv_epi8(best.triangle, _mm256_set1_epi32(static_cast<int>(index)),
                                       _mm256_castps_si256(mask));
}

// Every lane of hits: best's hit for the lanes of `lanes` that found a triangle, Hit{} for the
// others. Whole-register stores: hits is read back as registers (shadeLab8), and a register load
// of data just written lane by lane would stall on store forwarding.
RAYLAB_AVX2 inline void writeBest(const PacketBest& best, unsigned lanes, HitPacket& hits) {
    const __m256i bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    const __m256i found = _mm256_andnot_si256(
        _mm256_cmpeq_epi32(best.triangle, _mm256_set1_epi32(-1)),
        _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(lanes)), bits),
                           bits));
    const __m256 write = _mm256_castsi256_ps(found);
    const Hit none;
    _mm256_store_ps(hits.t, _mm256_blendv_ps(_mm256_set1_ps(none.t), best.t, write));
    _mm256_store_ps(
        hits.u, _mm256_blendv_ps(_mm256_set1_ps(none.u), _mm256_div_ps(best.e1, best.det), write));
    _mm256_store_ps(
        hits.v, _mm256_blendv_ps(_mm256_set1_ps(none.v), _mm256_div_ps(best.e2, best.det), write));
    _mm256_store_si256(reinterpret_cast<__m256i*>(hits.triangle),
                       _mm256_blendv_epi8(_mm256_set1_epi32(static_cast<int>(none.triangle)),
                                          best.triangle, found));
}

// Tests lane l's exact-fallback triangle and keeps it when closer.
RAYLAB_AVX2 inline void keepExact(PacketBest& best, const BvhTriangleBlock& block, int tri,
                                  const RayPacket& rays, unsigned lanes) {
    alignas(32) float bt[kWideLanes], e1[kWideLanes], e2[kWideLanes], det[kWideLanes];
    alignas(32) uint32_t bi[kWideLanes];
    _mm256_store_ps(bt, best.t);
    _mm256_store_ps(e1, best.e1);
    _mm256_store_ps(e2, best.e2);
    _mm256_store_ps(det, best.det);
    _mm256_store_si256(reinterpret_cast<__m256i*>(bi), best.triangle);
    const uint32_t index = block.sceneIndex[tri];
    for (unsigned m = lanes; m != 0; m &= m - 1) {
        const int l = __builtin_ctz(m);
        float t, u, v;
        if (intersectLane(block, tri, rays.ray(l), t, u, v) &&
            (t < bt[l] || (t == bt[l] && index < bi[l]))) {
            bt[l] = t;
            e1[l] = u;
            e2[l] = v;
            det[l] = 1.0f;
            bi[l] = index;
        }
    }
    best.t = _mm256_load_ps(bt);
    best.e1 = _mm256_load_ps(e1);
    best.e2 = _mm256_load_ps(e2);
    best.det = _mm256_load_ps(det);
    best.triangle = _mm256_load_si256(reinterpret_cast<const __m256i*>(bi));
}

} // namespace

RAYLAB_AVX2 unsigned closestHitPacket(const Bvh& bvh, const RayPacket& rays, HitPacket& hits) {
    PacketRays p;
    makePacket(rays, p);
    const unsigned lanes = p.lanes;
    if (lanes == 0) {
        hits.clear();
        return p.others;
    }
    PacketBest best{_mm256_set1_ps(kInfinity), _mm256_setzero_ps(), _mm256_setzero_ps(),
                    _mm256_set1_ps(1.0f), _mm256_set1_epi32(static_cast<int>(kNoTriangle))};
    __m256 limit = p.tMax; // per lane: min(tMax, best.t)
    const __m256 roundUp = _mm256_set1_ps(kBoxRoundUp);
    PacketEntry stack[kWideStackSize];
    int size = 0;
    uint32_t ref = 0;
    unsigned active = lanes;
    for (;;) {
        if (!isLeaf(ref)) {
            PacketEntry children[kWideLanes];
            const int n = hitChildren<true>(bvh.wideNodes[ref], p, limit, active, children);
            if (n > 0) {
                descend(children, n, stack, size, ref, active);
                continue;
            }
        } else {
            const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
            for (uint32_t b = blockCount(ref); b > 0; --b, ++block) {
                for (int tri = 0; tri < kWideLanes; ++tri) {
                    if (repeatsFirst(*block, tri)) {
                        continue;
                    }
                    const LaneHits h = intersectTriangle8(*block, tri, p);
                    if ((h.hits & active) != 0) {
                        keepCloser(best, h, h.hits & active, block->sceneIndex[tri]);
                    }
                    if ((h.exact & active) != 0) {
                        keepExact(best, *block, tri, rays, h.exact & active);
                    }
                }
            }
            limit = _mm256_min_ps(p.tMax, best.t);
        }
        // Next: the nearest pending entry that some lane may still find a closer hit in.
        for (;;) {
            if (size == 0) {
                writeBest(best, lanes, hits);
                return p.others;
            }
            const PacketEntry& e = stack[--size];
            const unsigned open =
                e.lanes & static_cast<unsigned>(_mm256_movemask_ps(
                              _mm256_cmp_ps(e.tNear, _mm256_mul_ps(limit, roundUp), _CMP_LE_OQ)));
            if (open != 0) {
                ref = e.ref;
                active = open;
                break;
            }
        }
    }
}

RAYLAB_AVX2 unsigned anyHitPacket(const Bvh& bvh, const RayPacket& rays, unsigned& occluded) {
    PacketRays p;
    makePacket(rays, p);
    occluded = 0;
    const unsigned lanes = p.lanes;
    if (lanes == 0) {
        return p.others;
    }
    unsigned found = 0; // lanes with a hit
    PacketEntry stack[kWideStackSize];
    int size = 0;
    uint32_t ref = 0;
    unsigned active = lanes;
    for (;;) {
        if (!isLeaf(ref)) {
            PacketEntry children[kWideLanes];
            const int n = hitChildren<false>(bvh.wideNodes[ref], p, p.tMax, active, children);
            if (n > 0) {
                descend(children, n, stack, size, ref, active);
                continue;
            }
        } else {
            const BvhTriangleBlock* block = &bvh.triangleBlocks[firstBlock(ref)];
            for (uint32_t b = blockCount(ref); b > 0 && active != 0; --b, ++block) {
                for (int tri = 0; tri < kWideLanes && active != 0; ++tri) {
                    if (repeatsFirst(*block, tri)) {
                        continue;
                    }
                    const LaneHits h = intersectTriangle8(*block, tri, p);
                    unsigned hit = h.hits & active;
                    for (unsigned m = h.exact & active & ~hit; m != 0; m &= m - 1) {
                        const int l = __builtin_ctz(m);
                        float t, u, v;
                        if (intersectLane(*block, tri, rays.ray(l), t, u, v)) {
                            hit |= 1u << l;
                        }
                    }
                    found |= hit;
                    active &= ~hit;
                }
            }
            if (found == lanes) {
                break;
            }
        }
        // Next: a pending entry with a lane still unanswered.
        for (;;) {
            if (size == 0) {
                active = 0;
                break;
            }
            const PacketEntry& e = stack[--size];
            if ((e.lanes & ~found) != 0) {
                ref = e.ref;
                active = e.lanes & ~found;
                break;
            }
        }
        if (active == 0) {
            break;
        }
    }
    occluded = found & lanes;
    return p.others;
}

} // namespace raylab

#else // not x86: buildBvh never builds the wide form, so these are never called.

namespace raylab {
unsigned closestHitPacket(const Bvh&, const RayPacket&, HitPacket&) { return 0; }
unsigned anyHitPacket(const Bvh&, const RayPacket&, unsigned&) { return 0; }
} // namespace raylab

#endif
