#include "test_meshes.h"

#include <cmath>
#include <random>
#include <vector>

namespace raylab::test {

Scene makePerturbedSphere(int rings, int segments, float radius, float perturbation,
                          uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(1.0f - perturbation, 1.0f + perturbation);
    const float pi = 3.14159265358979f;

    // Vertex 0 is the north pole, then (rings - 1) rows of `segments`, then the south pole.
    std::vector<glm::vec3> vertices;
    vertices.push_back({0.0f, radius * jitter(rng), 0.0f});
    for (int r = 1; r < rings; ++r) {
        const float theta = pi * static_cast<float>(r) / static_cast<float>(rings);
        for (int s = 0; s < segments; ++s) {
            const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
            const float k = radius * jitter(rng);
            vertices.push_back({k * std::sin(theta) * std::cos(phi), k * std::cos(theta),
                                k * std::sin(theta) * std::sin(phi)});
        }
    }
    vertices.push_back({0.0f, -radius * jitter(rng), 0.0f});
    const int south = static_cast<int>(vertices.size()) - 1;
    auto ring = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };

    Scene scene;
    scene.name = "perturbed sphere";
    scene.materials.push_back({"grey", glm::vec3(0.75f)});
    auto add = [&](int a, int b, int c) {
        scene.triangles.push_back({vertices[a], vertices[b], vertices[c], 0});
    };
    for (int s = 0; s < segments; ++s) {
        add(0, ring(1, s + 1), ring(1, s));
        add(south, ring(rings - 1, s), ring(rings - 1, s + 1));
        for (int r = 1; r < rings - 1; ++r) {
            add(ring(r, s), ring(r, s + 1), ring(r + 1, s + 1));
            add(ring(r, s), ring(r + 1, s + 1), ring(r + 1, s));
        }
    }
    return scene;
}

void addSquareZ(Scene& scene, glm::vec3 center, float half, uint32_t material) {
    const glm::vec3 a = center + glm::vec3(-half, -half, 0.0f);
    const glm::vec3 b = center + glm::vec3(half, -half, 0.0f);
    const glm::vec3 c = center + glm::vec3(half, half, 0.0f);
    const glm::vec3 d = center + glm::vec3(-half, half, 0.0f);
    scene.triangles.push_back({a, b, c, material});
    scene.triangles.push_back({a, c, d, material});
}

Scene makeQuadScene(float half, float depth, glm::vec3 diffuse) {
    Scene scene;
    scene.name = "quad";
    scene.materials.push_back({"quad", diffuse});
    addSquareZ(scene, {0.0f, 0.0f, depth}, half, 0);
    return scene;
}

} // namespace raylab::test
