#include "bench_rays.h"

#include "core/camera.h"
#include "core/sampling/hash.h"
#include "core/sampling/warp.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raylab::bench {

namespace {

// The triangle's geometric normal at a hit, turned to face the ray that made it.
glm::vec3 facingNormal(const Triangle& triangle, const Ray& ray) {
    const glm::vec3 normal = geometricNormal(triangle);
    return glm::dot(normal, ray.direction) > 0.0f ? -normal : normal;
}

} // namespace

int tileIndex(int x0, int y0, int width, int tileSize) {
    const int tilesX = (width + tileSize - 1) / tileSize;
    return (y0 / tileSize) * tilesX + x0 / tileSize;
}

Pixel pixelOf(const BenchRays& rays, std::size_t tile, std::size_t i) {
    const int ts = rays.tileSize;
    const auto tilesX = static_cast<std::size_t>((rays.width + ts - 1) / ts);
    const int x0 = static_cast<int>(tile % tilesX) * ts;
    const int y0 = static_cast<int>(tile / tilesX) * ts;
    const auto tileWidth = static_cast<std::size_t>(std::min(rays.width, x0 + ts) - x0);
    const std::size_t k = i - rays.primaryOffset[tile]; // row-major inside the tile
    return Pixel{x0 + static_cast<int>(k % tileWidth), y0 + static_cast<int>(k / tileWidth)};
}

std::vector<uint32_t> rayOfPrimary(const std::vector<std::size_t>& setPrimary,
                                   std::size_t primaryCount) {
    std::vector<uint32_t> ray(primaryCount, kNoRay);
    for (std::size_t j = 0; j < setPrimary.size(); ++j) {
        ray[setPrimary[j]] = static_cast<uint32_t>(j);
    }
    return ray;
}

BenchRays makePrimaryRays(const RenderSettings& settings, int tileSize) {
    BenchRays rays;
    rays.width = settings.width;
    rays.height = settings.height;
    rays.tileSize = tileSize;
    const PrimaryRays camera(settings.camera, settings.width, settings.height);
    const int tilesX = (settings.width + tileSize - 1) / tileSize;
    const int tilesY = (settings.height + tileSize - 1) / tileSize;
    rays.primary.reserve(static_cast<std::size_t>(settings.width) * settings.height);
    rays.primaryOffset.push_back(0);
    for (int ty = 0; ty < tilesY; ++ty) {
        for (int tx = 0; tx < tilesX; ++tx) {
            const int y1 = std::min(settings.height, (ty + 1) * tileSize);
            const int x1 = std::min(settings.width, (tx + 1) * tileSize);
            for (int y = ty * tileSize; y < y1; ++y) {
                for (int x = tx * tileSize; x < x1; ++x) {
                    rays.primary.push_back(
                        camera.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
                }
            }
            rays.primaryOffset.push_back(rays.primary.size());
        }
    }
    // No shadow or bounce rays yet.
    rays.shadowOffset.assign(rays.primaryOffset.size(), 0);
    rays.bounceOffset.assign(rays.primaryOffset.size(), 0);
    return rays;
}

void addShadowRays(BenchRays& rays, const std::vector<Hit>& hits, const Scene& scene,
                   const RenderSettings& settings) {
    rays.shadow.clear();
    rays.shadowOffset.assign(1, 0);
    rays.shadowPrimary.clear();
    for (std::size_t tile = 0; tile < rays.tiles(); ++tile) {
        for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
            if (!settings.shadows || !hits[i].found()) {
                continue;
            }
            // As directLight in core/lab_shading.cpp.
            const Ray& ray = rays.primary[i];
            const glm::vec3 point = ray.origin + hits[i].t * ray.direction;
            const glm::vec3 normal = facingNormal(scene.triangles[hits[i].triangle], ray);
            const glm::vec3 r = settings.light.position - point;
            const float distanceSquared = glm::dot(r, r);
            if (!(distanceSquared > 0.0f)) {
                continue;
            }
            const float distance = std::sqrt(distanceSquared);
            const glm::vec3 toLight = r / distance;
            if (!(glm::dot(toLight, normal) > 0.0f)) {
                continue;
            }
            rays.shadow.push_back(
                Ray{point, toLight, settings.shadowEpsilon, distance - settings.shadowEpsilon});
            rays.shadowPrimary.push_back(i);
        }
        rays.shadowOffset.push_back(rays.shadow.size());
    }
}

void addBounceRays(BenchRays& rays, const std::vector<Hit>& hits, const Scene& scene,
                   float epsilon) {
    // Salts the pixel hash, so that these numbers differ from the renderer's pixel jitter.
    constexpr uint32_t kBounceSalt = 0xb0a2ce11u;
    rays.bounce.clear();
    rays.bounceOffset.assign(1, 0);
    rays.bouncePrimary.clear();
    for (std::size_t tile = 0; tile < rays.tiles(); ++tile) {
        for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
            if (!hits[i].found()) {
                continue;
            }
            const Ray& ray = rays.primary[i];
            const glm::vec3 normal = facingNormal(scene.triangles[hits[i].triangle], ray);
            if (normal == glm::vec3(0.0f)) {
                continue; // no direction to bounce about (never for a triangle the BVH holds)
            }
            const Pixel pixel = pixelOf(rays, tile, i);
            const uint32_t seed = hash32(static_cast<uint32_t>(pixel.x) ^
                                         hash32(static_cast<uint32_t>(pixel.y) ^ kBounceSalt));
            const glm::vec2 u(unitFloat(seed), unitFloat(hash32(seed ^ 0x9e3779b9u)));
            const glm::vec3 direction = frameAround(normal).toWorld(cosineHemisphere(u));
            rays.bounce.push_back(
                Ray{ray.origin + hits[i].t * ray.direction, direction, epsilon, kInfinity});
            rays.bouncePrimary.push_back(i);
        }
        rays.bounceOffset.push_back(rays.bounce.size());
    }
}

namespace {
void packTiles(const std::vector<Ray>& rays, const std::vector<std::size_t>& rayOffset,
               std::vector<RayPacket>& packets, std::vector<std::size_t>& packetOffset) {
    packets.clear();
    packetOffset.assign(1, 0);
    for (std::size_t tile = 0; tile + 1 < rayOffset.size(); ++tile) {
        for (std::size_t i = rayOffset[tile]; i < rayOffset[tile + 1]; i += kPacketSize) {
            RayPacket packet;
            const std::size_t n = std::min<std::size_t>(kPacketSize, rayOffset[tile + 1] - i);
            for (std::size_t k = 0; k < n; ++k) {
                packet.set(static_cast<int>(k), rays[i + k]);
            }
            packets.push_back(packet);
        }
        packetOffset.push_back(packets.size());
    }
}
} // namespace

PacketedRays packRays(const BenchRays& rays) {
    PacketedRays packeted;
    packTiles(rays.primary, rays.primaryOffset, packeted.primary, packeted.primaryOffset);
    packTiles(rays.shadow, rays.shadowOffset, packeted.shadow, packeted.shadowOffset);
    return packeted;
}

} // namespace raylab::bench
