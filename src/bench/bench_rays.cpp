#include "bench_rays.h"

#include "core/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace raylab::bench {

int tileIndex(int x0, int y0, int width, int tileSize) {
    const int tilesX = (width + tileSize - 1) / tileSize;
    return (y0 / tileSize) * tilesX + x0 / tileSize;
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
    return rays;
}

void addShadowRays(BenchRays& rays, const std::vector<Hit>& hits, const Scene& scene,
                   const RenderSettings& settings) {
    rays.shadow.clear();
    rays.shadowOffset.assign(1, 0);
    rays.shadowPrimary.clear();
    for (std::size_t tile = 0; tile < rays.tiles(); ++tile) {
        for (std::size_t i = rays.primaryOffset[tile]; i < rays.primaryOffset[tile + 1]; ++i) {
            if (!hits[i].found()) {
                continue;
            }
            // As directLight in core/lab_shading.cpp.
            const Ray& ray = rays.primary[i];
            const Triangle& triangle = scene.triangles[hits[i].triangle];
            const glm::vec3 point = ray.origin + hits[i].t * ray.direction;
            glm::vec3 normal = geometricNormal(triangle);
            if (glm::dot(normal, ray.direction) > 0.0f) {
                normal = -normal;
            }
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
