#pragma once
// The lab's light model, per colour channel:
//   D = P * max(rhat . nhat, 0) / (4 pi |r|^2),  R = rho * (D + N)
// r runs from the surface point to the light, nhat is the geometric normal turned to face the
// incoming ray, rho the triangle's diffuse colour, N the constant indirect term. The point is in
// shadow when a triangle lies on the segment towards the light with eps < t < |r| - eps.
//
// The model is written once, in stages (surfaceAt, lightAt, labRadiance); shadeLab runs them for
// one ray, shadeLab8 (lab_shading_packet.cpp) for a packet of rays with the same results.

#include "bvh/bvh.h"
#include "bvh/bvh_frustum.h"
#include "bvh/bvh_packet.h"
#include "lights/point_light.h"
#include "ray_packet.h"
#include "render_settings.h"
#include "scene.h"

#include <cstdint>
#include <glm/vec3.hpp>

namespace raylab {

struct RayCounts {
    std::uint64_t primary = 0;
    std::uint64_t shadow = 0;
    std::uint64_t bounce = 0; // the path integrator's indirect rays

    std::uint64_t total() const { return primary + shadow + bounce; }
};

// The surface a camera ray hit: where, its facing normal nhat and its diffuse colour rho.
struct SurfacePoint {
    glm::vec3 point{0.0f};
    glm::vec3 facingNormal{0.0f};
    glm::vec3 rho{0.0f};
};

// `hit` must be found() for `ray`.
SurfacePoint surfaceAt(const Scene& scene, const Ray& ray, const Hit& hit);

// R = rho * (D + N).
glm::vec3 labRadiance(const RenderSettings& settings, const glm::vec3& rho,
                      const glm::vec3& direct);

// Direct light D arriving at point with facing normal nhat (0 when shadowed or facing away).
glm::vec3 directLight(const Bvh& bvh, const RenderSettings& settings, const glm::vec3& point,
                      const glm::vec3& facingNormal, RayCounts& counts);

// Radiance R along a camera ray; black when it hits nothing.
glm::vec3 shadeLab(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const Ray& ray, RayCounts& counts);

// The radiance of a packet's lanes: channel c of lane i is value[c][i].
struct alignas(32) RadiancePacket {
    float value[3][kPacketSize];
};

// Lane i of radiance = shadeLab(scene, bvh, settings, ray i, counts) for the lanes of
// rays.lanes, bit for bit and with the same counts; the other lanes are black. The camera rays
// and their shadow rays are traced as packets.
void shadeLab8(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
               const RayPacket& rays, RadiancePacket& radiance, RayCounts& counts);

// How shadeLabBlock traces a block's rays: through frustum candidates (bvh_frustum.h: one walk
// for the block's camera rays, one for its shadow rays), or packet by packet (16-ray packets in
// 4 x 4 tiles where the CPU has AVX2, else 8-ray packets). `ForScene` is tracingFor's choice.
enum class BlockTracing { ForScene, Frustums, Packets };

// The renderer's choice for this scene and CPU (Frustums or Packets): the one rule the renderer
// and raylab-bench share.
BlockTracing tracingFor(const Bvh& bvh);

// A pixel of an 8 x 8 block, from its top-left corner.
struct BlockPixel {
    int x, y;
};

// Where shadeLabBlock traces a full block (8 rows of 8 pixels) packet by packet, as four 4 x 4
// tiles, one 16-ray packet each (closestHit16): the pixel of lane `lane`
// of its packet `packet`, 0 <= both < kPacketSize. Packets 2t and 2t + 1 are tile t's upper
// and lower 4 x 2 pixels (tiles left to right, then top to bottom); lane i is column i % 4 and
// row i / 4 of its 4 x 2 pixels.
constexpr BlockPixel tilePixel(int packet, int lane) {
    const int tile = packet / 2;
    return BlockPixel{(tile % 2) * 4 + lane % 4, (tile / 2) * 4 + (packet % 2) * 2 + lane / 4};
}

// shadeLab8 for each of rays[0, count), 0 <= count <= kPacketSize, with the same results: the
// rays of an image block (camera rays from one origin), traced as `tracing` says (frustums only
// where the CPU has AVX2 and the BVH its 8-wide form; packets otherwise). `carry`, when given,
// carries the shadow packets' LastOccluder and the camera rays' CameraWalks (bvh_packet.h) from
// block to block: a caller passes one for the blocks of a tile, on one BVH.
void shadeLabBlock(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const RayPacket* rays, int count, RadiancePacket* radiance, RayCounts& counts,
                   BlockTracing tracing = BlockTracing::ForScene, TileCarry* carry = nullptr);

// The same for camera rays made by camera.through8 from image points in `rect` (the block's
// pixels): the camera rays' frustum comes from the rectangle (frustumOfImageRect), not the rays.
void shadeLabBlock(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                   const PrimaryRays& camera, const ImageRect& rect, const RayPacket* rays,
                   int count, RadiancePacket* radiance, RayCounts& counts,
                   BlockTracing tracing = BlockTracing::ForScene, TileCarry* carry = nullptr);

// The same for Ray records: radiance[i] for rays[0, count), 0 <= count <= kPacketSize.
void shadeLab8(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const Ray* rays,
               int count, glm::vec3* radiance, RayCounts& counts);

} // namespace raylab
