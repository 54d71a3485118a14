// The renderer's SIMD paths against their scalar references, bit for bit: 8-lane ray generation
// (PrimaryRays::through8 == through), 8-lane shading (shadeLab8 == shadeLab) and a whole pass
// (every pixel of renderPass == shadeLab of the ray through its sample point, stored or
// added to the sums before).

#include "core/bvh/bvh.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/render/renderer.h"
#include "core/sampling/hash.h"

#include <cstring>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace raylab {
namespace {

bool sameBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool sameRay(const Ray& a, const Ray& b) {
    return sameBits(a.origin, b.origin) && sameBits(a.direction, b.direction) &&
           std::memcmp(&a.tMin, &b.tMin, sizeof(float)) == 0 &&
           std::memcmp(&a.tMax, &b.tMax, sizeof(float)) == 0;
}

TEST(RenderSimd, Through8IsThroughBitForBit) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const int sizes[][2] = {{1, 1}, {7, 3}, {64, 64}, {500, 500}, {1280, 720}, {16384, 9}};
    const float fovs[] = {1e-3f, 1.0f, kLabVerticalFovDegrees, 90.0f, 150.0f, 179.9f};
    std::size_t checked = 0;
    for (const auto& size : sizes) {
        for (float fov : fovs) {
            for (int view = 0; view < 6; ++view) {
                Camera camera;
                camera.position = {unit(rng) * 20.0f - 10.0f, unit(rng) * 4.0f,
                                   unit(rng) * 20.0f - 10.0f};
                camera.yawDegrees = unit(rng) * 720.0f - 360.0f;
                camera.pitchDegrees = unit(rng) * 178.0f - 89.0f;
                camera.verticalFovDegrees = fov;
                const PrimaryRays rays(camera, size[0], size[1]);
                for (int packet = 0; packet < 40; ++packet) {
                    const int count = 1 + packet % 8;
                    float px[8];
                    float py[8];
                    for (int i = 0; i < count; ++i) {
                        // Pixel centres, jittered points, the image's corners and beyond.
                        px[i] = (unit(rng) * 1.2f - 0.1f) * static_cast<float>(size[0]);
                        py[i] = (unit(rng) * 1.2f - 0.1f) * static_cast<float>(size[1]);
                        if (packet % 3 == 0) {
                            px[i] = static_cast<float>(static_cast<int>(px[i])) + 0.5f;
                            py[i] = static_cast<float>(static_cast<int>(py[i])) + 0.5f;
                        }
                    }
                    RayPacket out;
                    rays.through8(px, py, count, out);
                    ASSERT_EQ(out.lanes, firstLanes(count));
                    for (int i = 0; i < count; ++i, ++checked) {
                        ASSERT_TRUE(sameRay(out.ray(i), rays.through(px[i], py[i])))
                            << px[i] << ", " << py[i] << " fov " << fov;
                    }
                }
            }
        }
    }
    EXPECT_GT(checked, 30000u);
}

// Random rays from inside and outside the box, some of them missing it; settings that switch on
// and off every branch of the light model.
TEST(RenderSimd, ShadeLab8IsShadeLabBitForBit) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int variant = 0; variant < 6; ++variant) {
        RenderSettings s;
        s.shadows = variant != 1;
        s.indirect = variant != 2;
        s.shadowEpsilon = variant == 3 ? 0.0f : 1e-3f;
        s.light.color = variant == 4 ? glm::vec3(0.2f, 0.7f, 1.0f) : glm::vec3(1.0f);
        if (variant == 5) {
            s.light.position = scene.triangles[0].v0; // a light on a surface
        }
        for (int packet = 0; packet < 500; ++packet) {
            const int count = 1 + packet % 8;
            Ray rays[8];
            for (int i = 0; i < count; ++i) {
                const float outside = packet % 2 == 0 ? 1.0f : 3.0f;
                rays[i].origin = glm::vec3(unit(rng), unit(rng), unit(rng)) * outside;
                rays[i].direction = glm::vec3(unit(rng), unit(rng), unit(rng));
            }
            glm::vec3 radiance[8];
            RayCounts packetCounts;
            shadeLab8(scene, bvh, s, rays, count, radiance, packetCounts);
            RayCounts singleCounts;
            for (int i = 0; i < count; ++i) {
                const glm::vec3 single = shadeLab(scene, bvh, s, rays[i], singleCounts);
                ASSERT_TRUE(sameBits(radiance[i], single)) << "variant " << variant;
            }
            ASSERT_EQ(packetCounts.primary, singleCounts.primary);
            ASSERT_EQ(packetCounts.shadow, singleCounts.shadow);
        }
    }
}

TEST(RenderSimd, EveryPixelOfAPassIsShadeLabOfItsSampleRay) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    RenderSettings s;
    s.width = 77; // rows of packets with a short last one
    s.height = 45;
    s.camera.yawDegrees = 7.0f;
    s.camera.pitchDegrees = -4.0f;
    s.threads = 2;
    const PrimaryRays rays(s.camera, s.width, s.height);
    // Sample 0 stores over whatever the sums held; later samples add to per-pixel earlier sums.
    const auto earlier = [&](int x, int y) {
        return glm::vec3(0.25f * static_cast<float>(x % 7), 1.0f / static_cast<float>(y + 3),
                         static_cast<float>((x * 31 + y) % 11) * 0.125f);
    };
    for (uint32_t sample : {0u, 1u, 5u}) {
        Film film(s.width, s.height);
        std::vector<PixelSum> sums(film.pixelCount());
        for (int y = 0; y < s.height; ++y) {
            for (int x = 0; x < s.width; ++x) {
                sums[static_cast<std::size_t>(y * s.width + x)].store(
                    sample == 0 ? glm::vec3(-1e30f) : earlier(x, y));
            }
        }
        film.assign(sums, 0, sample);
        ASSERT_TRUE(renderPass(scene, bvh, s, film));
        RayCounts counts;
        for (int y = 0; y < s.height; ++y) {
            for (int x = 0; x < s.width; ++x) {
                const PixelOffset o =
                    samplePixelOffset(static_cast<uint32_t>(x), static_cast<uint32_t>(y), sample);
                const glm::vec3 expected = shadeLab(
                    scene, bvh, s,
                    rays.through(static_cast<float>(x) + o.dx, static_cast<float>(y) + o.dy),
                    counts);
                PixelSum sum;
                sum.store(sample == 0 ? expected : earlier(x, y));
                if (sample != 0) {
                    sum.add(expected);
                }
                ASSERT_EQ(film.sumOf(static_cast<std::size_t>(y * s.width + x)), sum)
                    << x << ", " << y << " sample " << sample;
            }
        }
    }
}

} // namespace
} // namespace raylab
