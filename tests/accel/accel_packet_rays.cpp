#include "accel_packet_rays.h"

#include <cmath>
#include <limits>
#include <random>

namespace raylab::accel_test {

std::vector<Ray> cameraRays(const Camera& camera, int width, int height) {
    const PrimaryRays primary(camera, width, height);
    std::vector<Ray> rays;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            rays.push_back(
                primary.through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
        }
    }
    return rays;
}

std::vector<Ray> shadowRaysOf(const Bvh& bvh, const std::vector<Ray>& rays,
                              const glm::vec3& light) {
    std::vector<Ray> shadows;
    for (const Ray& ray : rays) {
        const Hit hit = closestHit(bvh, ray);
        if (hit.found()) {
            const glm::vec3 point = ray.origin + hit.t * ray.direction;
            const glm::vec3 r = light - point;
            const float distance = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
            shadows.push_back(Ray{point, r / distance, 1e-3f, distance - 1e-3f});
        }
    }
    return shadows;
}

std::vector<Ray> mixedDirectionRays(int count, bool perLane, uint32_t seed) {
    const glm::vec3 directions[8] = {{1, 0.1f, 0.2f},    {-0.1f, 1, 0.3f},    {0.2f, -0.3f, -1},
                                     {-1, 0.4f, 0.1f},   {0.3f, -1, 0.2f},    {0.1f, 0.2f, 1},
                                     {0.5f, 0.5f, 0.5f}, {-0.6f, 0.6f, -0.6f}};
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-0.5f, 0.5f);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const int direction = perLane ? (i * 3 + i / 8) % 8 : (i / 8) % 8;
        const float x = u(rng), y = u(rng), z = u(rng);
        rays.push_back(Ray{{x, y, z}, directions[direction]});
    }
    return rays;
}

void invalidateEveryThird(std::vector<Ray>& rays) {
    for (std::size_t i = 0; i < rays.size(); i += 3) {
        switch (i % 5) {
        case 0: rays[i].direction = glm::vec3(0.0f); break;
        case 1: rays[i].origin.y = std::numeric_limits<float>::quiet_NaN(); break;
        case 2: rays[i].direction.z = kInfinity; break;
        case 3: rays[i].tMax = std::numeric_limits<float>::quiet_NaN(); break;
        default: rays[i].tMin = std::numeric_limits<float>::quiet_NaN(); break;
        }
    }
}

} // namespace raylab::accel_test
