// shadeLab for a packet of camera rays: the camera rays, then the shadow rays of their lit hits,
// each traced as one packet (bvh_packet.h); the light model is lab_shading.cpp's stages.

#include "bvh_packet.h"
#include "lab_shading.h"

namespace raylab {

void shadeLab8(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const Ray* rays,
               int count, glm::vec3* radiance, RayCounts& counts) {
    Hit hits[kPacketSize];
    closestHit8(bvh, rays, count, hits);
    counts.primary += static_cast<std::uint64_t>(count);

    SurfacePoint surfaces[kPacketSize];
    glm::vec3 direct[kPacketSize];
    Ray shadowRays[kPacketSize];
    int shadowLane[kPacketSize];
    int shadowCount = 0;
    for (int i = 0; i < count; ++i) {
        if (!hits[i].found()) {
            continue;
        }
        surfaces[i] = surfaceAt(scene, rays[i], hits[i]);
        const LightSample sample = lightAt(settings, surfaces[i].point, surfaces[i].facingNormal);
        direct[i] = sample.direct;
        if (sample.needsShadowRay) {
            shadowRays[shadowCount] = sample.shadowRay;
            shadowLane[shadowCount++] = i;
        }
    }
    bool occluded[kPacketSize];
    anyHit8(bvh, shadowRays, shadowCount, occluded);
    counts.shadow += static_cast<std::uint64_t>(shadowCount);
    for (int j = 0; j < shadowCount; ++j) {
        if (occluded[j]) {
            direct[shadowLane[j]] = glm::vec3(0.0f);
        }
    }
    for (int i = 0; i < count; ++i) {
        radiance[i] =
            hits[i].found() ? labRadiance(settings, surfaces[i].rho, direct[i]) : glm::vec3(0.0f);
    }
}

} // namespace raylab
