#include "bench_blocks.h"

#include "core/bvh/bvh_frustum.h"
#include "core/bvh/bvh_packet.h"

#include <algorithm>

namespace raylab::bench {

BlockedRays blockRays(const BenchRays& rays, BlockLayout layout) {
    BlockedRays blocked;
    const std::vector<uint32_t> shadowOf = rayOfPrimary(rays.shadowPrimary, rays.primary.size());
    const int ts = rays.tileSize;
    const int tilesX = (rays.width + ts - 1) / ts;
    blocked.blockOffset.assign(1, 0);
    for (std::size_t tile = 0; tile < rays.tiles(); ++tile) {
        const int tx0 = static_cast<int>(tile % static_cast<std::size_t>(tilesX)) * ts;
        const int ty0 = static_cast<int>(tile / static_cast<std::size_t>(tilesX)) * ts;
        const int tx1 = std::min(rays.width, tx0 + ts);
        const int ty1 = std::min(rays.height, ty0 + ts);
        const int tileWidth = tx1 - tx0;
        for (int y0 = ty0; y0 < ty1; y0 += kPacketSize) {
            const int rows = std::min(kPacketSize, ty1 - y0);
            for (int x0 = tx0; x0 < tx1; x0 += kPacketSize) {
                const int count = std::min(kPacketSize, tx1 - x0);
                const bool tiles =
                    layout == BlockLayout::Tiles4x4 && rows == kPacketSize && count == kPacketSize;
                bool anyShadow = false;
                for (int r = 0; r < kPacketSize; ++r) {
                    RayPacket primary;
                    RayPacket shadow;
                    for (int i = 0; i < kPacketSize; ++i) {
                        uint32_t p = kNoRay;
                        uint32_t s = kNoRay;
                        if (r < rows && i < count) {
                            const BlockPixel pixel = tiles ? tilePixel(r, i) : BlockPixel{i, r};
                            // Row-major inside the tile (bench_rays.h).
                            const std::size_t index =
                                rays.primaryOffset[tile] +
                                static_cast<std::size_t>(y0 + pixel.y - ty0) * tileWidth +
                                static_cast<std::size_t>(x0 + pixel.x - tx0);
                            p = static_cast<uint32_t>(index);
                            primary.set(i, rays.primary[index]);
                            s = shadowOf[index];
                            if (s != kNoRay) {
                                shadow.set(i, rays.shadow[s]);
                                anyShadow = true;
                            }
                        }
                        blocked.primaryRay.push_back(p);
                        blocked.shadowRay.push_back(s);
                    }
                    blocked.primary.push_back(primary);
                    blocked.shadow.push_back(shadow);
                }
                blocked.rows.push_back(static_cast<uint8_t>(rows));
                blocked.rect.push_back(ImageRect{
                    static_cast<float>(x0) + 0.5f, static_cast<float>(y0) + 0.5f,
                    static_cast<float>(x0 + count) - 0.5f, static_cast<float>(y0 + rows) - 0.5f});
                blocked.blockShadowRays.push_back(anyShadow ? 1 : 0);
            }
        }
        blocked.blockOffset.push_back(blocked.rows.size());
    }
    return blocked;
}

BlockAnswers makeBlockAnswers(const BlockedRays& blocked) {
    BlockAnswers answers;
    answers.hits.resize(blocked.primary.size());
    answers.occluded.assign(blocked.shadow.size(), 0);
    answers.flags.assign(blocked.blocks(), 0);
    return answers;
}

void traceBlock(const Bvh& bvh, const PrimaryRays& camera, const BlockedRays& blocked,
                std::size_t block, const glm::vec3& light, bool shadowFrustum,
                BlockAnswers& answers) {
    const int count = blocked.rows[block];
    const std::size_t first = block * kPacketSize;
    const RayPacket* shadowRays = &blocked.shadow[first];
    unsigned* occluded = &answers.occluded[first];
    // As shadeLabBlock (core/lab_shading_block.cpp).
    const bool cameraCandidates = closestHitBlock(
        bvh, camera, blocked.rect[block], &blocked.primary[first], count, &answers.hits[first]);
    bool shadowCandidates = false;
    const bool shadows = blocked.blockShadowRays[block] != 0; // else occluded stays 0
    if (shadows && shadowFrustum) {
        shadowCandidates = anyHitBlock(bvh, shadowRays, count, light, occluded);
    } else if (shadows) {
        for (int k = 0; k < count; ++k) {
            occluded[k] = shadowRays[k].lanes != 0 ? anyHit8(bvh, shadowRays[k]) : 0u;
        }
    }
    answers.flags[block] = static_cast<uint8_t>((cameraCandidates ? kCameraCandidates : 0) |
                                                (shadowCandidates ? kShadowCandidates : 0));
}

void traceBlockInPacketPairs(const Bvh& bvh, const PrimaryRays& camera, const BlockedRays& blocked,
                             std::size_t block, BlockAnswers& answers, TileCarry& carry) {
    const int count = blocked.rows[block];
    const std::size_t first = block * kPacketSize;
    const RayPacket* rays = &blocked.primary[first];
    const RayPacket* shadowRays = &blocked.shadow[first];
    HitPacket* hits = &answers.hits[first];
    unsigned* occluded = &answers.occluded[first];
    const bool shadows = blocked.blockShadowRays[block] != 0; // else occluded stays 0
    // As shadeBlock and shadeRowPairs: a full block that sees only the background is answered
    // from its rectangle; else the camera rays (a block of 8 rows as 64 rays), then every pair's
    // shadow rays.
    const int paired = count / 2 * 2;
    if (fullBlock(rays, count) && imageRectMissesScene(bvh, camera, blocked.rect[block])) {
        for (int k = 0; k < count; ++k) {
            hits[k].clear();
        }
        return; // no hit, so no shadow ray
    }
    if (count == kPacketSize) {
        closestHit64(bvh, rays, hits, carry.cameraWalks);
    } else {
        for (int k = 0; k < paired; k += 2) {
            closestHit16(bvh, rays[k], rays[k + 1], hits[k], hits[k + 1]);
        }
    }
    for (int k = 0; k < paired && shadows; k += 2) {
        const unsigned both =
            (shadowRays[k].lanes | shadowRays[k + 1].lanes) != 0
                ? anyHit16(bvh, shadowRays[k], shadowRays[k + 1], carry.lastOccluder)
                : 0u;
        occluded[k] = both & 0xffu;
        occluded[k + 1] = both >> kPacketSize;
    }
    if (const int k = paired; k < count) {
        closestHit8(bvh, rays[k], hits[k]);
        if (shadows) {
            occluded[k] = shadowRays[k].lanes != 0 ? anyHit8(bvh, shadowRays[k]) : 0u;
        }
    }
}

} // namespace raylab::bench
