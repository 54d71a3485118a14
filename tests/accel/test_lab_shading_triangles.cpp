// The AVX2 shading (core/lab_shading_packet.cpp), which computes each hit triangle's normal as
// geometricNormal does, against the scalar stages (surfaceAt, lightAt, labRadiance) for triangles
// of every kind, for lanes without hits, and for materials edited after the build.

#include "accel_scenes.h"
#include "core/camera.h"
#include "core/cornell_box.h"
#include "core/integrators/lab_shading.h"
#include "core/integrators/lab_shading_stages.h"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>
#include <vector>

namespace raylab::accel_test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kZero = 0.0f;

bool sameBits(const glm::vec3& a, const glm::vec3& b) {
    return std::memcmp(&a, &b, sizeof(glm::vec3)) == 0;
}

// The triangle (0, 0, 0), scale * (1, 0, 0.25), scale * (0.5, 1, -0.5), with material m.
Triangle scaled(float scale, uint32_t m) {
    return Triangle{glm::vec3(0.0f), scale * glm::vec3(1.0f, 0.0f, 0.25f),
                    scale * glm::vec3(0.5f, 1.0f, -0.5f), m};
}

// Triangles of every kind among a soup large enough for several build threads and chunks:
// ordinary, degenerate (collinear, repeated vertices), tiny (normals from subnormal products, or
// none), huge (a length that overflows), non-finite vertices (skipped by the BVH), and a NaN
// triangle first, so that scene triangle 0 is never hit. Five materials.
Scene makeTrianglesOfEveryKind() {
    Scene soup = makeTriangleSoup(70000, 0.05f, 41);
    Scene scene;
    for (int m = 0; m < 5; ++m) {
        Material material;
        material.diffuse = glm::vec3(0.1f * static_cast<float>(m), 0.7f, 0.2f);
        scene.materials.push_back(material);
    }
    scene.triangles.push_back(
        {{kNaN, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 4}); // never hit
    for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
        Triangle t = soup.triangles[i];
        t.material = static_cast<uint32_t>(i % 5);
        scene.triangles.push_back(t);
    }
    const float inf = std::numeric_limits<float>::infinity();
    const Triangle odd[] = {
        {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, {2.0f, 2.0f, 2.0f}, 1}, // collinear
        {{0.3f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.3f}, {0.3f, 0.3f, 0.3f}, 2}, // a point
        {{0.0f, 0.0f, 0.0f}, {inf, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 3},  // infinite vertex
        {{0.0f, kNaN, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, kNaN}, 0}, // NaN vertices
        {{1e30f, 1e30f, 0.0f}, {-1e30f, 1e30f, 0.0f}, {0.0f, -1e30f, 0.0f}, 1},
        scaled(1e-10f, 2), // subnormal squared length
        scaled(1e-13f, 3), // squared length 0: no normal
        scaled(1e-20f, 4), // cross product 0
        scaled(1e9f, 0),   // large but finite
        scaled(1e10f, 1),  // squared length overflows: no normal
        scaled(1.0f, 2),
        {{-1e6f, 2.0f, 3.0f}, {1e6f, 2.0f, 3.0f + 1e-3f}, {0.0f, 2.0f + 1e-6f, 3.0f}, 3}, // sliver
    };
    for (const Triangle& t : odd) {
        scene.triangles.push_back(t);
    }
    return scene;
}

// Lane i of `stage` and `shadowRays` against the scalar stages for `ray` and `hit`.
void expectLaneEqualsScalar(const Scene& scene, const RenderSettings& settings, const Ray& ray,
                            const Hit& hit, const ShadingBeforeShadow& stage,
                            const RayPacket& shadowRays, int i) {
    const SurfacePoint s = surfaceAt(scene, ray, hit);
    const LightSample sample = lightAt(settings, s.point, s.facingNormal);
    const glm::vec3 lit = labRadiance(settings, s.rho, sample.direct);
    const glm::vec3 dark = labRadiance(settings, s.rho, glm::vec3(0.0f));
    const glm::vec3 laneLit(stage.lit[0][i], stage.lit[1][i], stage.lit[2][i]);
    const glm::vec3 laneDark(stage.dark[0][i], stage.dark[1][i], stage.dark[2][i]);
    ASSERT_TRUE(sameBits(laneLit, lit)) << "triangle " << hit.triangle;
    ASSERT_TRUE(sameBits(laneDark, dark)) << "triangle " << hit.triangle;
    ASSERT_EQ((shadowRays.lanes >> i) & 1u, sample.needsShadowRay ? 1u : 0u)
        << "triangle " << hit.triangle;
    if (sample.needsShadowRay) {
        const Ray shadow = shadowRays.ray(i);
        ASSERT_TRUE(sameBits(shadow.origin, sample.shadowRay.origin));
        ASSERT_TRUE(sameBits(shadow.direction, sample.shadowRay.direction));
        ASSERT_EQ(std::memcmp(&shadow.tMin, &sample.shadowRay.tMin, sizeof(float)), 0);
        ASSERT_EQ(std::memcmp(&shadow.tMax, &sample.shadowRay.tMax, sizeof(float)), 0);
    }
}

// Hits made up for every scene triangle, whether the BVH could find it or not, in packets whose
// lanes without a hit (kNoTriangle) change from packet to packet: beginShade equals the scalar
// stages lane by lane, and the lanes without a hit are +0 and cast no shadow ray (a triangle read
// at kNoTriangle would fault).
void expectShadingOfEveryTriangle(const Scene& scene, const RenderSettings& settings) {
    std::size_t next = 0;
    int lit = 0;
    for (unsigned pattern = 0; next < scene.triangles.size(); ++pattern) {
        const unsigned hitLanes = pattern % 7 == 0 ? 0xffu : (pattern * 97u + 13u) & 0xffu;
        RayPacket rays;
        HitPacket hits;
        Ray laneRays[kPacketSize];
        Hit laneHits[kPacketSize];
        for (int i = 0; i < kPacketSize; ++i) {
            const Triangle& t = scene.triangles[next % scene.triangles.size()];
            const glm::vec3 origin(0.25f * static_cast<float>(i - 4), 0.5f, -4.0f);
            const glm::vec3 centroid = (t.v0 + t.v1 + t.v2) / 3.0f;
            glm::vec3 toward = centroid - origin;
            if (!std::isfinite(glm::dot(toward, toward)) || glm::dot(toward, toward) == 0.0f) {
                toward = glm::vec3(0.0f, 0.0f, 1.0f);
            }
            laneRays[i] = Ray{origin, toward / std::sqrt(glm::dot(toward, toward))};
            rays.set(i, laneRays[i]);
            if ((hitLanes >> i) & 1u) {
                laneHits[i] = Hit{0.5f + 0.125f * static_cast<float>(i), 0.25f, 0.25f,
                                  static_cast<uint32_t>(next % scene.triangles.size())};
                hits.set(i, laneHits[i]);
                ++next;
            }
        }
        ShadingBeforeShadow stage;
        std::memset(&stage, 0xff, sizeof(stage)); // NaN: every lane must be written
        RayPacket shadowRays;
        RayCounts counts;
        beginShade(scene, settings, rays, hits, stage, shadowRays, counts);
        EXPECT_EQ(counts.shadow, static_cast<std::uint64_t>(laneCount(shadowRays.lanes)));
        for (int i = 0; i < kPacketSize; ++i) {
            if ((hitLanes >> i) & 1u) {
                expectLaneEqualsScalar(scene, settings, laneRays[i], laneHits[i], stage, shadowRays,
                                       i);
                if (::testing::Test::HasFatalFailure()) {
                    return;
                }
                lit += stage.lit[1][i] > stage.dark[1][i] ? 1 : 0;
            } else {
                for (int c = 0; c < 3; ++c) {
                    ASSERT_EQ(std::memcmp(&stage.lit[c][i], &kZero, sizeof(float)), 0);
                    ASSERT_EQ(std::memcmp(&stage.dark[c][i], &kZero, sizeof(float)), 0);
                }
                ASSERT_EQ((shadowRays.lanes >> i) & 1u, 0u);
            }
        }
    }
    EXPECT_GT(lit, 1000);
}

TEST(LabShadingTriangles, PacketsEqualTheScalarStagesForTrianglesOfEveryKind) {
    if (!bvhSimdSupported()) {
        GTEST_SKIP() << "this CPU has no AVX2: beginShade is not run";
    }
    const Scene scene = makeTrianglesOfEveryKind();
    RenderSettings settings;
    settings.light.position = {0.2f, 0.3f, -2.0f};
    expectShadingOfEveryTriangle(scene, settings);
    settings.shadows = false;
    expectShadingOfEveryTriangle(scene, settings);
}

// shadeLab8 and shadeLabBlock (through frustums and packet by packet) against shadeLab, pixel
// for pixel; returns the lanes' radiance.
std::vector<glm::vec3> expectPacketsEqualScalar(const Scene& scene, const Bvh& bvh,
                                                const RenderSettings& settings) {
    const PrimaryRays primary(settings.camera, settings.width, settings.height);
    std::vector<glm::vec3> image;
    for (int y0 = 0; y0 < settings.height; y0 += kPacketSize) {
        for (int x0 = 0; x0 < settings.width; x0 += kPacketSize) {
            RayPacket packets[kPacketSize];
            for (int r = 0; r < kPacketSize; ++r) {
                for (int i = 0; i < kPacketSize; ++i) {
                    packets[r].set(i, primary.through(static_cast<float>(x0 + i) + 0.5f,
                                                      static_cast<float>(y0 + r) + 0.5f));
                }
            }
            RadiancePacket block[kPacketSize], tiles[kPacketSize];
            RayCounts counts;
            shadeLabBlock(scene, bvh, settings, packets, kPacketSize, block, counts,
                          BlockTracing::Frustums);
            shadeLabBlock(scene, bvh, settings, packets, kPacketSize, tiles, counts,
                          BlockTracing::Packets);
            for (int r = 0; r < kPacketSize; ++r) {
                RadiancePacket single;
                shadeLab8(scene, bvh, settings, packets[r], single, counts);
                for (int i = 0; i < kPacketSize; ++i) {
                    const glm::vec3 expected =
                        shadeLab(scene, bvh, settings, packets[r].ray(i), counts);
                    const glm::vec3 fromBlock(block[r].value[0][i], block[r].value[1][i],
                                              block[r].value[2][i]);
                    const glm::vec3 fromTiles(tiles[r].value[0][i], tiles[r].value[1][i],
                                              tiles[r].value[2][i]);
                    const glm::vec3 fromPacket(single.value[0][i], single.value[1][i],
                                               single.value[2][i]);
                    EXPECT_TRUE(sameBits(fromBlock, expected)) << x0 + i << ", " << y0 + r;
                    EXPECT_TRUE(sameBits(fromTiles, expected)) << x0 + i << ", " << y0 + r;
                    EXPECT_TRUE(sameBits(fromPacket, expected)) << x0 + i << ", " << y0 + r;
                    image.push_back(expected);
                }
            }
        }
    }
    return image;
}

// Materials are read at shading time, not kept in the Bvh: colours edited after buildBvh shade
// with the new colours, with the SIMD form and without it.
TEST(LabShadingTriangles, MaterialsEditedAfterTheBuildShadeWithTheirNewColours) {
    Scene scene = makeCornellBox();
    ASSERT_GE(scene.materials.size(), 2u);
    BvhBuildOptions scalarOnly;
    scalarOnly.simd = false;
    const Bvh simd = buildBvh(scene), scalar = buildBvh(scene, scalarOnly);
    RenderSettings settings;
    settings.width = 48;
    settings.height = 40;
    const std::vector<glm::vec3> before = expectPacketsEqualScalar(scene, simd, settings);
    for (Material& m : scene.materials) {
        m.diffuse = glm::vec3(m.diffuse.z, 0.5f * m.diffuse.x, 1.0f - m.diffuse.y);
    }
    const std::vector<glm::vec3> after = expectPacketsEqualScalar(scene, simd, settings);
    EXPECT_EQ(expectPacketsEqualScalar(scene, scalar, settings), after);
    int changed = 0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        changed += after[i] != before[i] ? 1 : 0;
    }
    EXPECT_GT(changed, static_cast<int>(after.size()) / 2);
}

} // namespace
} // namespace raylab::accel_test
