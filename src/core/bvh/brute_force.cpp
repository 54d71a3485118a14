#include "bvh/brute_force.h"

#include "triangle_intersection.h"

namespace raylab {

Hit closestHitBruteForce(const Scene& scene, const Ray& ray) {
    WatertightRay wray(ray);
    Hit hit;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& tri = scene.triangles[i];
        float t, u, v;
        // Each accepted hit lowers tMax, so a later triangle at the same t never replaces it.
        if (isValidTriangle(tri) && intersectTriangle(wray, tri.v0, tri.v1, tri.v2, t, u, v)) {
            hit = Hit{t, u, v, i};
            wray.tMax = t;
        }
    }
    return hit;
}

bool anyHitBruteForce(const Scene& scene, const Ray& ray) {
    const WatertightRay wray(ray);
    for (const Triangle& tri : scene.triangles) {
        float t, u, v;
        if (isValidTriangle(tri) && intersectTriangle(wray, tri.v0, tri.v1, tri.v2, t, u, v)) {
            return true;
        }
    }
    return false;
}

} // namespace raylab
