#include "triangle_intersection.h"

#include "finite.h"

#include <cmath>
#include <glm/common.hpp>
#include <utility>

namespace raylab {

WatertightRay::WatertightRay(const Ray& ray) : origin(ray.origin), tMin(ray.tMin), tMax(ray.tMax) {
    const glm::vec3& d = ray.direction;
    valid = isFinite(ray.origin) && isFinite(d) && (d.x != 0.0f || d.y != 0.0f || d.z != 0.0f) &&
            !std::isnan(ray.tMin) && !std::isnan(ray.tMax);
    if (!valid) {
        return;
    }
    const glm::vec3 a = glm::abs(d);
    kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = kz == 2 ? 0 : kz + 1;
    ky = kx == 2 ? 0 : kx + 1;
    // Swapping kx and ky when the ray runs along -kz keeps the triangles' winding, so the sign
    // of the edge functions means the same for every ray.
    if (d[kz] < 0.0f) {
        std::swap(kx, ky);
    }
    shearX = d[kx] / d[kz];
    shearY = d[ky] / d[kz];
    shearZ = 1.0f / d[kz];
}

bool intersectTriangle(const WatertightRay& ray, const glm::vec3& v0, const glm::vec3& v1,
                       const glm::vec3& v2, float& t, float& u, float& v) {
    if (!ray.valid) {
        return false;
    }
    // Vertices relative to the origin, then sheared so that the ray runs along +z.
    const glm::vec3 a = v0 - ray.origin;
    const glm::vec3 b = v1 - ray.origin;
    const glm::vec3 c = v2 - ray.origin;
    const float ax = a[ray.kx] - ray.shearX * a[ray.kz];
    const float ay = a[ray.ky] - ray.shearY * a[ray.kz];
    const float bx = b[ray.kx] - ray.shearX * b[ray.kz];
    const float by = b[ray.ky] - ray.shearY * b[ray.kz];
    const float cx = c[ray.kx] - ray.shearX * c[ray.kz];
    const float cy = c[ray.ky] - ray.shearY * c[ray.kz];

    // Edge functions: twice the signed areas of the sub-triangles the ray's foot makes with
    // each edge (e0 opposite v0, and so on).
    float e0 = cx * by - cy * bx;
    float e1 = ax * cy - ay * cx;
    float e2 = bx * ay - by * ax;
    // On an edge the float result can be zero when the exact one is not: decide in double,
    // where the products of floats are exact, so neighbours sharing the edge agree.
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
        e0 = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
        e1 = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
        e2 = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
    }
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) {
        return false;
    }
    const float det = e0 + e1 + e2;
    if (det == 0.0f || !std::isfinite(det)) {
        return false;
    }
    const float az = ray.shearZ * a[ray.kz];
    const float bz = ray.shearZ * b[ray.kz];
    const float cz = ray.shearZ * c[ray.kz];
    const float tScaled = e0 * az + e1 * bz + e2 * cz;
    const float hitT = tScaled / det;
    // Strict bounds; a NaN or infinite t fails both.
    if (!(hitT > ray.tMin && hitT < ray.tMax)) {
        return false;
    }
    t = hitT;
    u = e1 / det;
    v = e2 / det;
    return true;
}

} // namespace raylab
