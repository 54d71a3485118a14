#pragma once
// The benchmark's workload, generated once before any timing: one primary ray per pixel through
// the pinhole camera, and the lab's shadow ray (lab_shading.cpp) for each primary hit that faces
// the light. Rays are stored tile by tile, so threads take whole tiles of contiguous rays.

#include "core/ray.h"
#include "core/ray_packet.h"
#include "core/render_settings.h"
#include "core/scene.h"

#include <cstddef>
#include <vector>

namespace raylab::bench {

struct BenchRays {
    int width = 0, height = 0;
    int tileSize = 32;
    std::vector<Ray> primary;               // tile-major, row-major inside a tile
    std::vector<std::size_t> primaryOffset; // tile i's primary rays: [offset[i], offset[i + 1])
    std::vector<Ray> shadow;                // tile-major, in the order of their primary hits
    std::vector<std::size_t> shadowOffset;  // likewise
    std::vector<std::size_t>
        shadowPrimary; // shadow[j] is the shadow ray of primary[shadowPrimary[j]]
    std::size_t tiles() const { return primaryOffset.empty() ? 0 : primaryOffset.size() - 1; }
    std::size_t total() const { return primary.size() + shadow.size(); }
};

// The same rays in packets of 8 (ray_packet.h): each tile's rays, 8 consecutive ones a packet
// (the tile's last packet may be partial). Ray k of a tile is lane k % 8 of the tile's packet
// k / 8.
struct PacketedRays {
    std::vector<RayPacket> primary;
    std::vector<std::size_t> primaryOffset; // tile i's packets: [offset[i], offset[i + 1])
    std::vector<RayPacket> shadow;
    std::vector<std::size_t> shadowOffset;
};

PacketedRays packRays(const BenchRays& rays);

// Tile i covers the same pixels as forEachTile's tile i (parallel_tiles.h) for this size.
int tileIndex(int x0, int y0, int width, int tileSize);

// The primary rays of settings.camera at settings.width x settings.height.
BenchRays makePrimaryRays(const RenderSettings& settings, int tileSize = 32);

// Adds the shadow rays of the primary hits (hits[i] belongs to rays.primary[i]).
void addShadowRays(BenchRays& rays, const std::vector<Hit>& hits, const Scene& scene,
                   const RenderSettings& settings);

} // namespace raylab::bench
