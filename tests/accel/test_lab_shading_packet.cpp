// shadeLab8 (packets of camera and shadow rays) against shadeLab, pixel for pixel.

#include "accel_scenes.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/lab_shading.h"

#include <cstring>
#include <gtest/gtest.h>

namespace raylab::accel_test {
namespace {

void expectPacketShadingEqualsSingle(const Scene& scene, RenderSettings settings) {
    const Bvh bvh = buildBvh(scene);
    const PrimaryRays primary(settings.camera, settings.width, settings.height);
    RayCounts single, packets;
    for (int y = 0; y < settings.height; ++y) {
        for (int x0 = 0; x0 < settings.width; x0 += 8) {
            const int count = std::min(8, settings.width - x0);
            Ray rays[8];
            glm::vec3 radiance[8];
            for (int i = 0; i < count; ++i) {
                rays[i] = primary.through(static_cast<float>(x0 + i) + 0.5f,
                                          static_cast<float>(y) + 0.5f);
            }
            shadeLab8(scene, bvh, settings, rays, count, radiance, packets);
            for (int i = 0; i < count; ++i) {
                const glm::vec3 expected = shadeLab(scene, bvh, settings, rays[i], single);
                ASSERT_EQ(std::memcmp(&expected, &radiance[i], sizeof(glm::vec3)), 0)
                    << "pixel " << x0 + i << ", " << y;
            }
        }
    }
    EXPECT_EQ(packets.primary, single.primary);
    EXPECT_EQ(packets.shadow, single.shadow);
}

TEST(LabShadingPacket, CornellBoxWithAndWithoutShadows) {
    RenderSettings settings;
    settings.width = 101; // not a multiple of 8: partial packets at the row ends
    settings.height = 64;
    expectPacketShadingEqualsSingle(makeCornellBox(), settings);
    settings.shadows = false;
    expectPacketShadingEqualsSingle(makeCornellBox(), settings);
    settings.shadows = true;
    settings.shadowEpsilon = 0.0f; // shadow acne: self-hits at t just above 0
    expectPacketShadingEqualsSingle(makeCornellBox(), settings);
}

TEST(LabShadingPacket, SoupSeenFromOutside) {
    RenderSettings settings;
    settings.width = 64;
    settings.height = 48;
    settings.light.position = {0.5f, 2.0f, -1.5f};
    expectPacketShadingEqualsSingle(makeTriangleSoup(5000, 0.1f, 31), settings);
}

} // namespace
} // namespace raylab::accel_test
