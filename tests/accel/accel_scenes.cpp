#include "accel_scenes.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace raylab::accel_test {

namespace {

glm::vec3 uniformIn(std::mt19937& rng, float extent) {
    std::uniform_real_distribution<float> u(-extent, extent);
    const float x = u(rng), y = u(rng), z = u(rng);
    return {x, y, z};
}

} // namespace

Scene makeTriangleSoup(int count, float size, uint32_t seed) {
    std::mt19937 rng(seed);
    Scene scene;
    scene.materials.push_back({});
    for (int i = 0; i < count; ++i) {
        const glm::vec3 c = uniformIn(rng, 1.0f);
        scene.triangles.push_back(
            {c + uniformIn(rng, size), c + uniformIn(rng, size), c + uniformIn(rng, size), 0});
    }
    return scene;
}

Scene makeTripledSoup() {
    Scene scene = makeTriangleSoup(1500, 0.15f, 29);
    const std::vector<Triangle> once = scene.triangles;
    scene.triangles.insert(scene.triangles.end(), once.rbegin(), once.rend());
    scene.triangles.insert(scene.triangles.end(), once.begin(), once.end());
    return scene;
}

Scene makeSoupWithDegenerateTriangles() {
    Scene scene = makeTriangleSoup(1000, 0.2f, 3);
    scene.triangles[10].v0.x = std::numeric_limits<float>::quiet_NaN();
    scene.triangles[20].v1.y = std::numeric_limits<float>::infinity();
    scene.triangles[40].v1 = scene.triangles[40].v0;                                   // zero area
    scene.triangles[50].v2 = 0.5f * (scene.triangles[50].v0 + scene.triangles[50].v1); // collinear
    return scene;
}

Scene makeHeightField(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> bump(-0.05f, 0.05f);
    std::vector<float> h(static_cast<std::size_t>((n + 1) * (n + 1)));
    for (std::size_t i = 0; i < h.size(); ++i) {
        const float x =
            static_cast<float>(i % static_cast<std::size_t>(n + 1)) / static_cast<float>(n);
        const float y =
            static_cast<float>(i / static_cast<std::size_t>(n + 1)) / static_cast<float>(n);
        h[i] = 0.3f * std::sin(6.0f * x) * std::cos(5.0f * y) + bump(rng);
    }
    auto vertex = [&](int i, int j) {
        const float step = 2.0f / static_cast<float>(n);
        return glm::vec3(-1.0f + step * static_cast<float>(i), -1.0f + step * static_cast<float>(j),
                         h[static_cast<std::size_t>(j * (n + 1) + i)]);
    };
    Scene scene;
    scene.materials.push_back({});
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            scene.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), 0});
            scene.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1), 0});
        }
    }
    return scene;
}

Scene makeClosedSphere(int rings, int segments, float radius, float perturbation, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(1.0f - perturbation, 1.0f + perturbation);
    const float pi = 3.14159265358979f;
    std::vector<glm::vec3> points; // north pole, rings - 1 latitude rows, south pole
    points.push_back({0.0f, radius * jitter(rng), 0.0f});
    for (int r = 1; r < rings; ++r) {
        const float theta = pi * static_cast<float>(r) / static_cast<float>(rings);
        for (int s = 0; s < segments; ++s) {
            const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
            const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            points.push_back(d * (radius * jitter(rng)));
        }
    }
    points.push_back({0.0f, -radius * jitter(rng), 0.0f});
    const auto south = static_cast<int>(points.size()) - 1;
    auto at = [&](int r, int s) {
        return points[static_cast<std::size_t>(1 + (r - 1) * segments + (s % segments))];
    };
    Scene scene;
    scene.materials.push_back({});
    for (int s = 0; s < segments; ++s) {
        scene.triangles.push_back({points[0], at(1, s + 1), at(1, s), 0});
        scene.triangles.push_back(
            {points[static_cast<std::size_t>(south)], at(rings - 1, s), at(rings - 1, s + 1), 0});
        for (int r = 1; r < rings - 1; ++r) {
            scene.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1), 0});
            scene.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s), 0});
        }
    }
    return scene;
}

std::vector<Ray> makeRandomRays(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        Ray ray;
        ray.origin = uniformIn(rng, 2.0f);
        ray.direction = glm::normalize(uniformIn(rng, 1.0f) - ray.origin);
        rays.push_back(ray);
    }
    return rays;
}

std::vector<Ray> makeAxisAlignedRays(int count, float extent, uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        Ray ray;
        ray.origin = uniformIn(rng, extent);
        const int axis = i % 3;
        const float sign = (i / 3) % 2 == 0 ? 1.0f : -1.0f;
        // The other components are +0 or -0, alternating.
        const float zero = (i / 6) % 2 == 0 ? 0.0f : -0.0f;
        ray.direction = glm::vec3(zero);
        ray.direction[axis] = sign;
        rays.push_back(ray);
    }
    return rays;
}

} // namespace raylab::accel_test
