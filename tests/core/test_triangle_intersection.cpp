// The watertight ray-triangle test: exact hits, edges, closed meshes, and hostile input.

#include "core/bvh/brute_force.h"
#include "core/triangle_intersection.h"
#include "test_meshes.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <random>

namespace raylab {
namespace {

const glm::vec3 kV0{0.0f, 0.0f, 2.0f};
const glm::vec3 kV1{1.0f, 0.0f, 2.0f};
const glm::vec3 kV2{0.0f, 1.0f, 2.0f};

bool hits(const Ray& ray, float& t, float& u, float& v) {
    return intersectTriangle(WatertightRay(ray), kV0, kV1, kV2, t, u, v);
}

bool hits(const Ray& ray) {
    float t, u, v;
    return hits(ray, t, u, v);
}

TEST(TriangleIntersection, KnownHitHasExactDistanceAndBarycentrics) {
    float t = 0, u = 0, v = 0;
    ASSERT_TRUE(hits(Ray{{0.25f, 0.5f, 0.0f}, {0.0f, 0.0f, 1.0f}}, t, u, v));
    EXPECT_FLOAT_EQ(t, 2.0f);
    EXPECT_FLOAT_EQ(u, 0.25f); // weight of v1 = x
    EXPECT_FLOAT_EQ(v, 0.5f);  // weight of v2 = y

    // An oblique, unnormalised direction: t is in units of |direction|.
    const glm::vec3 target{0.2f, 0.3f, 2.0f};
    const glm::vec3 origin{-1.0f, 2.0f, -3.0f};
    ASSERT_TRUE(hits(Ray{origin, 0.5f * (target - origin)}, t, u, v));
    EXPECT_NEAR(t, 2.0f, 1e-5f);
    EXPECT_NEAR(u, 0.2f, 1e-5f);
    EXPECT_NEAR(v, 0.3f, 1e-5f);
}

TEST(TriangleIntersection, BothWindingsAndBothSidesHit) {
    float t, u, v;
    const WatertightRay fromFront(Ray{{0.2f, 0.2f, 0.0f}, {0.0f, 0.0f, 1.0f}});
    const WatertightRay fromBack(Ray{{0.2f, 0.2f, 4.0f}, {0.0f, 0.0f, -1.0f}});
    EXPECT_TRUE(intersectTriangle(fromFront, kV0, kV1, kV2, t, u, v));
    EXPECT_TRUE(intersectTriangle(fromFront, kV0, kV2, kV1, t, u, v));
    EXPECT_TRUE(intersectTriangle(fromBack, kV0, kV1, kV2, t, u, v));
    EXPECT_FLOAT_EQ(t, 2.0f);
}

TEST(TriangleIntersection, MissesJustOutsideEachEdge) {
    const float inf = std::numeric_limits<float>::infinity();
    const float below = std::nextafter(0.0f, -inf);
    const float justOver = std::nextafter(0.5f, inf);
    const glm::vec3 forward{0.0f, 0.0f, 1.0f};
    // Edge v0-v1 lies on y = 0, edge v0-v2 on x = 0, edge v1-v2 on x + y = 1.
    EXPECT_FALSE(hits(Ray{{0.3f, below, 0.0f}, forward}));
    EXPECT_FALSE(hits(Ray{{below, 0.3f, 0.0f}, forward}));
    EXPECT_FALSE(hits(Ray{{0.5f, justOver, 0.0f}, forward}));
    EXPECT_FALSE(hits(Ray{{justOver, 0.5f, 0.0f}, forward}));
    // ... and the same points nudged inside hit.
    EXPECT_TRUE(hits(Ray{{0.3f, 1e-6f, 0.0f}, forward}));
    EXPECT_TRUE(hits(Ray{{1e-6f, 0.3f, 0.0f}, forward}));
    EXPECT_TRUE(hits(Ray{{0.5f, 0.49999f, 0.0f}, forward}));
}

TEST(TriangleIntersection, RespectsExclusiveDistanceBounds) {
    const glm::vec3 origin{0.2f, 0.2f, 0.0f};
    const glm::vec3 forward{0.0f, 0.0f, 1.0f};
    EXPECT_FALSE(hits(Ray{origin, forward, 0.0f, 2.0f}));
    EXPECT_TRUE(hits(Ray{origin, forward, 0.0f, std::nextafter(2.0f, 3.0f)}));
    EXPECT_FALSE(hits(Ray{origin, forward, 2.0f, 3.0f}));
    EXPECT_FALSE(hits(Ray{origin, -forward})); // behind the origin
}

TEST(TriangleIntersection, SignedZeroAndUnitDirectionComponents) {
    const float directions[][3] = {{0.0f, 0.0f, 1.0f},   {-0.0f, 0.0f, 1.0f}, {0.0f, -0.0f, 1.0f},
                                   {-0.0f, -0.0f, 1.0f}, {1.0f, 0.0f, 0.0f},  {0.0f, 1.0f, -0.0f}};
    // Each direction, from an origin placed so the ray meets the triangle's interior.
    for (const auto& d : directions) {
        const glm::vec3 dir{d[0], d[1], d[2]};
        const glm::vec3 target{0.25f, 0.25f, 2.0f};
        const Triangle tri{kV0, kV1, kV2, 0};
        float t, u, v;
        if (dir.z != 0.0f) {
            ASSERT_TRUE(intersectTriangle(WatertightRay(Ray{target - dir, dir}), tri.v0, tri.v1,
                                          tri.v2, t, u, v));
            EXPECT_FLOAT_EQ(t, 1.0f);
        } else {
            // Parallel to the triangle's plane: never a hit.
            EXPECT_FALSE(intersectTriangle(WatertightRay(Ray{target - dir, dir}), tri.v0, tri.v1,
                                           tri.v2, t, u, v));
        }
    }
}

TEST(TriangleIntersection, NonFiniteOrZeroRaysMissWithoutHanging) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const glm::vec3 origin{0.2f, 0.2f, 0.0f};
    EXPECT_FALSE(hits(Ray{origin, {nan, 0.0f, 1.0f}}));
    EXPECT_FALSE(hits(Ray{origin, {0.0f, 0.0f, inf}}));
    EXPECT_FALSE(hits(Ray{{nan, 0.2f, 0.0f}, {0.0f, 0.0f, 1.0f}}));
    EXPECT_FALSE(hits(Ray{{0.2f, -inf, 0.0f}, {0.0f, 0.0f, 1.0f}}));
    EXPECT_FALSE(hits(Ray{origin, {0.0f, 0.0f, 0.0f}}));
    EXPECT_FALSE(hits(Ray{origin, {0.0f, 0.0f, 1.0f}, nan, inf}));
    EXPECT_FALSE(hits(Ray{origin, {0.0f, 0.0f, 1.0f}, 0.0f, nan}));
}

TEST(TriangleIntersection, DegenerateAndNonFiniteTrianglesNeverHit) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    Scene scene;
    scene.materials.push_back({});
    const glm::vec3 p{0.5f, 0.5f, 2.0f};
    scene.triangles.push_back({p, p, p, 0});                                      // a point
    scene.triangles.push_back({{0, 0, 2}, {1, 1, 2}, {2, 2, 2}, 0});              // collinear
    scene.triangles.push_back({{0, 0, 2}, {1, 1, 2}, {0, 0, 2}, 0});              // repeated
    scene.triangles.push_back({{nan, 0, 2}, {1, 0, 2}, {0, 1, 2}, 0});            // NaN
    scene.triangles.push_back({{-inf, -inf, 2}, {inf, -inf, 2}, {0, inf, 2}, 0}); // infinite
    for (const Triangle& tri : scene.triangles) {
        EXPECT_FALSE(isValidTriangle(tri));
    }
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 3.0f);
    for (int i = 0; i < 2000; ++i) {
        const Ray ray{{unit(rng), unit(rng), 0.0f}, {0.0f, 0.0f, 1.0f}};
        EXPECT_FALSE(closestHitBruteForce(scene, ray).found());
        EXPECT_FALSE(anyHitBruteForce(scene, ray));
    }
    // A ray exactly along the collinear "triangle" too.
    EXPECT_FALSE(anyHitBruteForce(scene, Ray{{-1, -1, 2}, {1, 1, 0}}));
}

TEST(TriangleIntersection, SharedEdgeOfAQuadNeverLetsARayThrough) {
    // Two triangles sharing the diagonal of a quad; rays aimed at points on the diagonal.
    Scene quad = test::makeQuadScene(1.0f, 3.0f, glm::vec3(0.5f));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> along(-1.0f, 1.0f);
    std::uniform_real_distribution<float> from(-5.0f, 5.0f);
    for (int i = 0; i < 20000; ++i) {
        const float s = along(rng);
        const glm::vec3 onDiagonal{s, s, 3.0f};
        const glm::vec3 origin{from(rng), from(rng), -2.0f};
        EXPECT_TRUE(anyHitBruteForce(quad, Ray{origin, onDiagonal - origin}))
            << "ray through " << s << "," << s << " slipped through the diagonal";
    }
}

TEST(TriangleIntersection, RandomRaysFromInsideAClosedSphereAllHit) {
    const Scene sphere = test::makePerturbedSphere(24, 48, 1.0f, 0.05f, 1234);
    ASSERT_EQ(sphere.triangles.size(), 2u * 48u * 23u);
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> inside(-0.4f, 0.4f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    int misses = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec3 origin{inside(rng), inside(rng), inside(rng)};
        const glm::vec3 direction{gauss(rng), gauss(rng), gauss(rng)};
        const Hit hit = closestHitBruteForce(sphere, Ray{origin, direction});
        misses += hit.found() ? 0 : 1;
    }
    EXPECT_EQ(misses, 0);
}

TEST(TriangleIntersection, RaysAimedExactlyAtVerticesAndEdgeMidpointsHit) {
    const Scene sphere = test::makePerturbedSphere(12, 24, 1.0f, 0.08f, 77);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> inside(-0.3f, 0.3f);
    int misses = 0;
    int tested = 0;
    for (const Triangle& tri : sphere.triangles) {
        for (const glm::vec3& target : {tri.v0, tri.v1, tri.v2, 0.5f * (tri.v0 + tri.v1),
                                        0.5f * (tri.v1 + tri.v2), 0.5f * (tri.v2 + tri.v0)}) {
            const glm::vec3 origin{inside(rng), inside(rng), inside(rng)};
            misses += closestHitBruteForce(sphere, Ray{origin, target - origin}).found() ? 0 : 1;
            ++tested;
        }
    }
    EXPECT_EQ(misses, 0) << "of " << tested;
    // Rays along the axes from the centre pass through the poles exactly.
    for (const glm::vec3& axis : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0),
                                  glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)}) {
        EXPECT_TRUE(closestHitBruteForce(sphere, Ray{glm::vec3(0.0f), axis}).found());
    }
}

TEST(TriangleIntersection, ClosestHitPicksNearestAndLowerIndexOnTies) {
    Scene scene = test::makeQuadScene(1.0f, 5.0f, glm::vec3(0.5f));
    test::addSquareZ(scene, {0.0f, 0.0f, 3.0f}, 1.0f, 0); // triangles 2, 3: nearer
    test::addSquareZ(scene, {0.0f, 0.0f, 3.0f}, 1.0f, 0); // triangles 4, 5: coincident with 2, 3
    const Hit hit = closestHitBruteForce(scene, Ray{{0.5f, -0.2f, 0.0f}, {0.0f, 0.0f, 1.0f}});
    ASSERT_TRUE(hit.found());
    EXPECT_FLOAT_EQ(hit.t, 3.0f);
    EXPECT_EQ(hit.triangle, 2u);
}

// isValidTriangle's SSE2 lanes decide as the plain formula does: every coordinate finite and
// |cross(v1 - v0, v2 - v0)|^2 (glm's cross and dot, in their order) positive and finite, also
// where that square underflows to 0 or overflows, for triangles of every scale.
TEST(TriangleIntersection, ValidTrianglesAreThoseOfThePlainFormula) {
    const auto plain = [](const Triangle& t) {
        for (const glm::vec3& p : {t.v0, t.v1, t.v2}) {
            for (int a = 0; a < 3; ++a) {
                if (!std::isfinite(p[a])) {
                    return false;
                }
            }
        }
        const glm::vec3 n = glm::cross(t.v1 - t.v0, t.v2 - t.v0);
        const float area2 = glm::dot(n, n);
        return area2 > 0.0f && std::isfinite(area2);
    };
    const float specials[] = {std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              0.0f,
                              -0.0f,
                              std::numeric_limits<float>::max(),
                              std::numeric_limits<float>::denorm_min()};
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> exponent(-70, 70), pick(0, 15);
    int valid = 0, invalid = 0;
    for (int i = 0; i < 200000; ++i) {
        const float scale = std::ldexp(1.0f, exponent(rng)); // area2 from underflow to overflow
        Triangle t;
        glm::vec3* v[3] = {&t.v0, &t.v1, &t.v2};
        for (glm::vec3* p : v) {
            for (int a = 0; a < 3; ++a) {
                const int k = pick(rng);
                (*p)[a] = k < 7 && i % 5 == 0 ? specials[k] : scale * unit(rng);
            }
        }
        if (i % 7 == 0) {
            t.v2 = t.v0 + (t.v1 - t.v0) * 0.5f; // collinear, or nearly after rounding
        }
        t.material = static_cast<uint32_t>(i);
        const bool expected = plain(t);
        ASSERT_EQ(isValidTriangle(t), expected) << i;
        (expected ? valid : invalid) += 1;
    }
    EXPECT_GT(valid, 50000);
    EXPECT_GT(invalid, 20000);
}

} // namespace
} // namespace raylab
