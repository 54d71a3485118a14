// shadeLabBlock: through frustums, the packets of an image block share one frustum walk for their
// camera rays and one for their shadow rays (bvh_frustum.h), and packets whose frustum holds too
// many triangles are traced one by one through the BVH; packet by packet, a block is traced as
// packets of 16 rays (closestHit16: one packet where the CPU has AVX-512, two of 8 rays where it
// has AVX2 alone): a full block as four 4 x 4 tiles, else its rows two by two, and the camera rays
// of a block of 8 rows as one packet of 64 (closestHit64: one walk of the BVH for the four tiles),
// or none when the block's image rectangle misses the scene (imageRectMissesScene); without AVX2,
// row by row. Either way each lane's radiance is shadeLab8's.

#include "bvh/bvh_frustum.h"
#include "bvh/bvh_packet.h"
#include "integrators/lab_shading.h"
#include "integrators/lab_shading_stages.h"
#include "watertight_avx2.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <utility>

namespace raylab {

namespace {

// Packets whose every lane is written before it is read: not zeroed first (RayPacket::Unset).
template <typename Packet, std::size_t... I>
std::array<Packet, sizeof...(I)> unsetPackets(std::index_sequence<I...>) {
    return {((void)I, Packet(RayPacket::Unset{}))...};
}

// shadeLab8 of packets rays[0, 2 * pairs): the camera rays of all 8 rows at once as 64 rays
// (closestHit64) when there are 8, else two by two as 16 rays (closestHit16), and their shading
// up to the shadow test; then every pair's shadow rays (anyHit16). raylab-bench traces a block's
// 16-ray packets in this order too (traceBlockInPacketPairs); there, with Embree in the process,
// each pair's shadow rays straight after its camera rays traced Sponza's 16-ray packets 0.90-0.91x
// as fast, where without Embree in the process, and in the renderer's passes, the two orders run as
// fast (why is not known). The shadow rays test carry.lastOccluder first and leave their last
// occluder in it (LastOccluder); 64 camera rays walk as carry.cameraWalks chooses. `background`:
// every camera ray is known to miss (imageRectMissesScene), so none is traced.
// 1 <= pairs <= kPacketSize / 2. Call only where bvhSimdSupported() and bvh.wideNodes is not
// empty.
void shadeRowPairs(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const RayPacket* rays, int pairs, RadiancePacket* radiance, RayCounts& counts,
                   TileCarry& carry, bool background = false) {
    auto hits = unsetPackets<HitPacket>(std::make_index_sequence<kPacketSize>());
    ShadingBeforeShadow stages[kPacketSize];
    auto shadowRays = unsetPackets<RayPacket>(std::make_index_sequence<kPacketSize>());
    const int count = 2 * pairs;
    if (background) {
        for (int k = 0; k < count; ++k) {
            hits[k].clear();
        }
    } else if (count == kPacketSize) {
        closestHit64(bvh, rays, hits.data(), carry.cameraWalks);
    } else {
        for (int k = 0; k < count; k += 2) {
            closestHit16(bvh, rays[k], rays[k + 1], hits[k], hits[k + 1]);
        }
    }
    for (int k = 0; k < count; ++k) {
        counts.primary += static_cast<std::uint64_t>(laneCount(rays[k].lanes));
        beginShade(scene, settings, rays[k], hits[k], stages[k], shadowRays[k], counts);
    }
    for (int k = 0; k < count; k += 2) {
        const unsigned occluded =
            (shadowRays[k].lanes | shadowRays[k + 1].lanes) != 0
                ? anyHit16(bvh, shadowRays[k], shadowRays[k + 1], carry.lastOccluder)
                : 0u;
        finishShade(stages[k], occluded & 0xffu, radiance[k]);
        finishShade(stages[k + 1], occluded >> kPacketSize, radiance[k + 1]);
    }
}

// Lanes 0-3 of `out` from upper[xUpper, xUpper + 4), lanes 4-7 from lower[xLower, xLower + 4),
// in one 32-byte store: the 16-ray set-up's 32-byte load of the field is then forwarded from one
// store, not two (with two 16-byte copies the bench's lab passes on the bunny were 0.5-1% slower).
RAYLAB_AVX2 inline void gatherField(const float* upper, int xUpper, const float* lower, int xLower,
                                    float* out) {
    _mm256_store_ps(out,
                    _mm256_set_m128(_mm_loadu_ps(lower + xLower), _mm_loadu_ps(upper + xUpper)));
}

// Tile packet p of a full block (tilePixel) from the block's rows: every lane set. Call only
// where the CPU has AVX2.
RAYLAB_AVX2 void gatherTile(const RayPacket* rows, int p, RayPacket& tile) {
    const BlockPixel upper = tilePixel(p, 0), lower = tilePixel(p, 4);
    const RayPacket& a = rows[upper.y];
    const RayPacket& b = rows[lower.y];
    for (int axis = 0; axis < 3; ++axis) {
        gatherField(a.origin[axis], upper.x, b.origin[axis], lower.x, tile.origin[axis]);
        gatherField(a.direction[axis], upper.x, b.direction[axis], lower.x, tile.direction[axis]);
    }
    gatherField(a.tMin, upper.x, b.tMin, lower.x, tile.tMin);
    gatherField(a.tMax, upper.x, b.tMax, lower.x, tile.tMax);
    tile.lanes = firstLanes(kPacketSize);
}

// shadeRowPairs of a full block's rows (8 packets of 8 lanes) regrouped as four 4 x 4 tiles
// (tilePixel): a square of pixels is a narrower frustum than two rows, so fewer nodes pass its
// tests. radiance[r] is row r's, as for the rows; `background` as shadeRowPairs takes it.
void shadeTiles(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                const RayPacket* rows, RadiancePacket* radiance, RayCounts& counts,
                TileCarry& carry, bool background) {
    auto tiles = unsetPackets<RayPacket>(std::make_index_sequence<kPacketSize>());
    for (int p = 0; p < kPacketSize; ++p) {
        gatherTile(rows, p, tiles[p]);
    }
    RadiancePacket tileRadiance[kPacketSize];
    shadeRowPairs(scene, bvh, settings, tiles.data(), kPacketSize / 2, tileRadiance, counts, carry,
                  background);
    for (int p = 0; p < kPacketSize; ++p) {
        for (int half = 0; half < 2; ++half) {
            const BlockPixel corner = tilePixel(p, half * 4);
            for (int c = 0; c < 3; ++c) {
                std::memcpy(&radiance[corner.y].value[c][corner.x],
                            &tileRadiance[p].value[c][half * 4], 4 * sizeof(float));
            }
        }
    }
}

// shadeLabBlock, with the camera rays' frustum from `camera` and `rect` when camera is set.
void shadeBlock(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                const PrimaryRays* camera, const ImageRect& rect, const RayPacket* rays, int count,
                RadiancePacket* radiance, RayCounts& counts, BlockTracing tracing,
                TileCarry* carry) {
    static const bool simd = bvhSimdSupported();
    if (tracing == BlockTracing::ForScene) {
        tracing = tracingFor(bvh);
    }
    if (tracing == BlockTracing::Packets || !simd || bvh.wideNodes.empty()) {
        int k = 0;
        if (simd && !bvh.wideNodes.empty()) {
            TileCarry blockOnly;
            TileCarry& carried = carry != nullptr ? *carry : blockOnly;
            if (fullBlock(rays, count)) {
                // A block that sees only the background is answered from its rectangle.
                const bool background =
                    camera != nullptr && imageRectMissesScene(bvh, *camera, rect);
                shadeTiles(scene, bvh, settings, rays, radiance, counts, carried, background);
                return;
            }
            if (count >= 2) {
                k = count / 2 * 2;
                shadeRowPairs(scene, bvh, settings, rays, count / 2, radiance, counts, carried);
            }
        }
        for (; k < count; ++k) {
            shadeLab8(scene, bvh, settings, rays[k], radiance[k], counts);
        }
        return;
    }
    auto hits = unsetPackets<HitPacket>(std::make_index_sequence<kPacketSize>());
    if (camera) {
        closestHitBlock(bvh, *camera, rect, rays, count, hits.data());
    } else {
        closestHitBlock(bvh, rays, count, hits.data());
    }
    ShadingBeforeShadow stages[kPacketSize];
    auto shadowRays = unsetPackets<RayPacket>(std::make_index_sequence<kPacketSize>());
    for (int k = 0; k < count; ++k) {
        counts.primary += static_cast<std::uint64_t>(laneCount(rays[k].lanes));
        beginShade(scene, settings, rays[k], hits[k], stages[k], shadowRays[k], counts);
    }
    // Shadow rays run from their hit point towards the light and stop short of it (tMin =
    // epsilon >= 0, tMax = |r| - epsilon): segments ending at the light.
    unsigned occluded[kPacketSize];
    if (settings.shadowEpsilon >= 0.0f) {
        anyHitBlock(bvh, shadowRays.data(), count, settings.light.position, occluded);
    } else {
        for (int k = 0; k < count; ++k) {
            occluded[k] = shadowRays[k].lanes != 0 ? anyHit8(bvh, shadowRays[k]) : 0u;
        }
    }
    for (int k = 0; k < count; ++k) {
        finishShade(stages[k], occluded[k], radiance[k]);
    }
}

} // namespace

BlockTracing tracingFor(const Bvh& bvh) {
    // Frustums pay where a scene is a few large triangles (the lab's box: raylab-bench's renderer
    // passes 1.22x the 16-ray packets' samples per second on 1 thread, 1.26x in passes of 16
    // samples, where the bench traces the box's rays alone about as fast either way, 0.98-1.00x:
    // the blocks share their frustum and shading set-up). For meshes of tens of thousands of
    // triangles the walks that end over kMaxFrustumCandidates cost more than they save (bunny,
    // dragon and Sponza 0.92 to 0.95x), so those are traced packet by packet. In between it depends
    // on how many triangles a block sees: a sphere of 3,970 triangles over a floor, framed as
    // raylab-bench frames a mesh, 1.12-1.14x (passes of 16 samples 1.16-1.20x); of
    // 16,130, 1.06-1.13x (1.09-1.24x); the bunny's 16,301-triangle version 0.95-0.97x (1.00-1.02x).
    constexpr std::size_t kMaxFrustumSceneTriangles = 4096;
    static const bool simd = bvhSimdSupported();
    return simd && !bvh.wideNodes.empty() && bvh.leafReferences <= kMaxFrustumSceneTriangles
               ? BlockTracing::Frustums
               : BlockTracing::Packets;
}

void shadeLabBlock(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const RayPacket* rays, int count, RadiancePacket* radiance, RayCounts& counts,
                   BlockTracing tracing, TileCarry* carry) {
    shadeBlock(scene, bvh, settings, nullptr, ImageRect{}, rays, count, radiance, counts, tracing,
               carry);
}

void shadeLabBlock(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const PrimaryRays& camera, const ImageRect& rect, const RayPacket* rays,
                   int count, RadiancePacket* radiance, RayCounts& counts, BlockTracing tracing,
                   TileCarry* carry) {
    shadeBlock(scene, bvh, settings, &camera, rect, rays, count, radiance, counts, tracing, carry);
}

} // namespace raylab
