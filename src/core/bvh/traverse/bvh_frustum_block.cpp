// A block's packets traced through one frustum's candidates, or through the BVH when they do
// not fit (bvh_frustum.h). Where the CPU has AVX-512 the rows go two by two on 16 lanes either
// way: through the candidates (closestHitCandidates16, anyHitCandidates16) the box's blocks
// 1.13x as fast as row by row (raylab-bench, 1 thread), its lab passes 1.11-1.13x; through the
// BVH (closestHit16, anyHit16) the bunny's blocks 1.28x, the dragon's 1.19x.

#include "bvh/bvh_frustum.h"
#include "bvh/bvh_packet.h"
#include "bvh/traverse/bvh_packet16_traverse.h"

namespace raylab {

namespace {

// closestHit8 for each packet, through the candidates of `frustum` when `framed` and they fit:
// two packets at a time on 16 lanes where the CPU has AVX-512.
bool closestHitInFrustum(const Bvh& bvh, bool framed, const RayFrustum& frustum,
                         const RayPacket* rays, int count, HitPacket* hits) {
    FrustumCandidates candidates;
    const bool culled = framed && frustumCandidates(bvh, frustum, candidates);
    const auto one = [&](int j) {
        if (culled) {
            closestHitCandidates(bvh, candidates, rays[j], hits[j]);
        } else {
            closestHit8(bvh, rays[j], hits[j]);
        }
    };
    static const bool pairs = bvhPacket16Supported();
    int k = 0;
    for (; pairs && k + 1 < count; k += 2) {
        if (!culled) {
            closestHit16(bvh, rays[k], rays[k + 1], hits[k], hits[k + 1]);
        } else if (!closestHitCandidates16(bvh, candidates, rays[k], rays[k + 1], hits[k],
                                           hits[k + 1])) {
            one(k);
            one(k + 1);
        }
    }
    for (; k < count; ++k) {
        one(k);
    }
    return culled;
}

} // namespace

bool closestHitBlock(const Bvh& bvh, const RayPacket* rays, int count, HitPacket* hits) {
    RayFrustum frustum;
    const bool framed = frustumOfRays(bvh, rays, count, frustum);
    return closestHitInFrustum(bvh, framed, frustum, rays, count, hits);
}

bool closestHitBlock(const Bvh& bvh, const PrimaryRays& camera, const ImageRect& rect,
                     const RayPacket* rays, int count, HitPacket* hits) {
    RayFrustum frustum;
    const bool framed = frustumOfImageRect(bvh, camera, rect, frustum);
    return closestHitInFrustum(bvh, framed, frustum, rays, count, hits);
}

bool anyHitBlock(const Bvh& bvh, const RayPacket* rays, int count, const glm::vec3& end,
                 unsigned* occluded) {
    RayFrustum frustum;
    FrustumCandidates candidates;
    const bool culled = frustumOfSegments(bvh, rays, count, end, frustum) &&
                        frustumCandidates(bvh, frustum, candidates);
    const auto one = [&](int j) -> unsigned {
        if (rays[j].lanes == 0) {
            return 0;
        }
        return culled ? anyHitCandidates(bvh, candidates, rays[j]) : anyHit8(bvh, rays[j]);
    };
    static const bool pairs = bvhPacket16Supported();
    int k = 0;
    for (; pairs && k + 1 < count; k += 2) {
        unsigned both = 0;
        const bool anyRays = (rays[k].lanes | rays[k + 1].lanes) != 0;
        if (anyRays && !culled) {
            both = anyHit16(bvh, rays[k], rays[k + 1]);
        } else if (anyRays && !anyHitCandidates16(bvh, candidates, rays[k], rays[k + 1], both)) {
            both = one(k) | one(k + 1) << kPacketSize;
        }
        occluded[k] = both & 0xffu;
        occluded[k + 1] = both >> kPacketSize;
    }
    for (; k < count; ++k) {
        occluded[k] = one(k);
    }
    return culled;
}

} // namespace raylab
