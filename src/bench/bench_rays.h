#pragma once
// The benchmark's workload, generated once before any timing: one primary ray per pixel through
// the pinhole camera, the lab's shadow ray (lab_shading.cpp) for each primary hit that faces the
// light, and, for the bounce workload, one diffuse bounce ray from each primary hit. Rays are
// stored tile by tile, so threads take whole tiles of contiguous rays.

#include "core/ray.h"
#include "core/ray_packet.h"
#include "core/render_settings.h"
#include "core/scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab::bench {

// An index that names no ray.
inline constexpr uint32_t kNoRay = 0xffffffffu;

// What raylab-bench traces: camera and shadow rays, or those and one diffuse bounce per hit.
enum class Workload { Primary, Bounce };

struct BenchRays {
    int width = 0, height = 0;
    int tileSize = 32;
    std::vector<Ray> primary;               // tile-major, row-major inside a tile
    std::vector<std::size_t> primaryOffset; // tile i's primary rays: [offset[i], offset[i + 1])
    std::vector<Ray> shadow;                // tile-major, in the order of their primary hits
    std::vector<std::size_t> shadowOffset;  // likewise
    std::vector<std::size_t>
        shadowPrimary;       // shadow[j] is the shadow ray of primary[shadowPrimary[j]]
    std::vector<Ray> bounce; // empty for the primary workload; otherwise as the shadow rays
    std::vector<std::size_t> bounceOffset;
    std::vector<std::size_t> bouncePrimary;
    std::size_t tiles() const { return primaryOffset.empty() ? 0 : primaryOffset.size() - 1; }
    std::size_t total() const { return primary.size() + shadow.size() + bounce.size(); }
};

// Pixel (x, y) of the image, y counting down.
struct Pixel {
    int x = 0, y = 0;
};

// The pixel of primary ray i, which lies in tile `tile`.
Pixel pixelOf(const BenchRays& rays, std::size_t tile, std::size_t i);

// For each primary ray, the index of its ray in a set whose ray j belongs to primary ray
// setPrimary[j] (BenchRays::shadowPrimary, bouncePrimary), or kNoRay.
std::vector<uint32_t> rayOfPrimary(const std::vector<std::size_t>& setPrimary,
                                   std::size_t primaryCount);

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

// Adds the shadow rays of the primary hits (hits[i] belongs to rays.primary[i]); none when
// settings.shadows is off.
void addShadowRays(BenchRays& rays, const std::vector<Hit>& hits, const Scene& scene,
                   const RenderSettings& settings);

// Adds one diffuse bounce ray for each primary hit (hits[i] belongs to rays.primary[i]): from
// the hit point, in a cosine-weighted direction about the triangle's geometric normal turned
// to face the primary ray, closest hit with epsilon < t < infinity (epsilon: the shadow
// epsilon). The direction's two random numbers come from a hash of the pixel (x, y) alone, so
// every run, thread count and tracer sees the same rays.
void addBounceRays(BenchRays& rays, const std::vector<Hit>& hits, const Scene& scene,
                   float epsilon);

} // namespace raylab::bench
