// A block's packets traced through one frustum's candidates, or one by one when it does not fit
// (bvh_frustum.h).

#include "bvh/bvh_frustum.h"
#include "bvh/bvh_packet.h"

namespace raylab {

namespace {

// closestHit8 for each packet, through the candidates of `frustum` when `framed` and they fit.
bool closestHitInFrustum(const Bvh& bvh, bool framed, const RayFrustum& frustum,
                         const RayPacket* rays, int count, HitPacket* hits) {
    FrustumCandidates candidates;
    const bool culled = framed && frustumCandidates(bvh, frustum, candidates);
    for (int k = 0; k < count; ++k) {
        if (culled) {
            closestHitCandidates(bvh, candidates, rays[k], hits[k]);
        } else {
            closestHit8(bvh, rays[k], hits[k]);
        }
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
    for (int k = 0; k < count; ++k) {
        occluded[k] = 0;
        if (rays[k].lanes != 0) {
            occluded[k] =
                culled ? anyHitCandidates(bvh, candidates, rays[k]) : anyHit8(bvh, rays[k]);
        }
    }
    return culled;
}

} // namespace raylab
