// shadeLab for a packet of camera rays: the camera rays, then the shadow rays of their lit hits,
// each traced as one packet (bvh_packet.h). The light model is lab_shading.cpp's stages; where the
// CPU has AVX2, the 8 lanes run those stages' operations side by side (shadeLanesAvx2), each
// rounded as the scalar stage rounds it (IEEE single precision, no contraction: core builds with
// -ffp-contract=off), so the radiance is bit for bit the scalar path's (tests/core checks it).

#include "bvh_packet.h"
#include "lab_shading.h"
#include "watertight_avx2.h"

#include <cstddef>

namespace raylab {

namespace {

// The layouts shadeLanesAvx2's gathers assume.
static_assert(sizeof(Triangle) == 10 * sizeof(float) && offsetof(Triangle, v1) == 12 &&
              offsetof(Triangle, v2) == 24);
static_assert(sizeof(Ray) == 8 * sizeof(float) && offsetof(Ray, direction) == 12);
static_assert(sizeof(Hit) == 4 * sizeof(float) && offsetof(Hit, t) == 0 &&
              offsetof(Hit, triangle) == 12);

constexpr float kFourPi = 12.566370614359172f; // as lab_shading.cpp

void shadeLanesScalar(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                      const Ray* rays, int count, const Hit* hits, glm::vec3* radiance,
                      RayCounts& counts) {
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

RAYLAB_AVX2 inline __m256 dot8(const __m256 a[3], const __m256 b[3]) {
    // glm::dot: (a.x*b.x + a.y*b.y) + a.z*b.z
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[0], b[0]), _mm256_mul_ps(a[1], b[1])),
                         _mm256_mul_ps(a[2], b[2]));
}

// base[index[i]] in the lanes of mask, 0 in the others.
RAYLAB_AVX2 inline __m256 gather8(__m256 mask, const float* base, __m256i index) {
    return _mm256_mask_i32gather_ps(_mm256_setzero_ps(), base, index, mask, 4);
}

// surfaceAt, lightAt and labRadiance for 8 lanes; lanes that missed (or >= count) give black.
RAYLAB_AVX2 void shadeLanesAvx2(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                                const Ray* rays, int count, const Hit* hits, glm::vec3* radiance,
                                RayCounts& counts) {
    // Lane inputs, gathered into structure-of-arrays form; lanes without a hit read nothing and
    // hold zeros (their results are masked out).
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i active = _mm256_cmpgt_epi32(_mm256_set1_epi32(count), lane);
    const __m256i triangle = _mm256_mask_i32gather_epi32(
        _mm256_set1_epi32(-1), reinterpret_cast<const int*>(&hits[0].triangle),
        _mm256_slli_epi32(lane, 2), active, 4);
    const __m256i found =
        _mm256_andnot_si256(_mm256_cmpeq_epi32(triangle, _mm256_set1_epi32(-1)), active);
    const unsigned hitLanes = static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(found)));
    if (hitLanes == 0) {
        for (int i = 0; i < count; ++i) {
            radiance[i] = glm::vec3(0.0f);
        }
        return;
    }
    const __m256 zero = _mm256_setzero_ps();
    const __m256 foundMask = _mm256_castsi256_ps(found);
    // Triangle records are 10 floats (v0, v1, v2, material); rays 8 (origin, direction, tMin,
    // tMax); hits 4 (t, u, v, triangle).
    const __m256i triangleBase = _mm256_and_si256(
        _mm256_add_epi32(_mm256_slli_epi32(triangle, 3), _mm256_slli_epi32(triangle, 1)), found);
    const float* vertices = &scene.triangles[0].v0.x;
    const __m256i rayBase = _mm256_slli_epi32(lane, 3);
    const float* rayFloats = &rays[0].origin.x;
    __m256 dir[3], e1[3], e2[3], o[3];
    for (int k = 0; k < 3; ++k) {
        o[k] = gather8(foundMask, rayFloats, _mm256_add_epi32(rayBase, _mm256_set1_epi32(k)));
        dir[k] = gather8(foundMask, rayFloats, _mm256_add_epi32(rayBase, _mm256_set1_epi32(3 + k)));
        const __m256 a =
            gather8(foundMask, vertices, _mm256_add_epi32(triangleBase, _mm256_set1_epi32(k)));
        e1[k] = _mm256_sub_ps(
            gather8(foundMask, vertices, _mm256_add_epi32(triangleBase, _mm256_set1_epi32(3 + k))),
            a);
        e2[k] = _mm256_sub_ps(
            gather8(foundMask, vertices, _mm256_add_epi32(triangleBase, _mm256_set1_epi32(6 + k))),
            a);
    }
    const __m256 t =
        _mm256_mask_i32gather_ps(zero, &hits[0].t, _mm256_slli_epi32(lane, 2), foundMask, 4);
    alignas(32) float rho[3][8] = {};
    for (unsigned m = hitLanes; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        const glm::vec3& diffuse =
            scene.materials[scene.triangles[hits[i].triangle].material].diffuse;
        rho[0][i] = diffuse.x;
        rho[1][i] = diffuse.y;
        rho[2][i] = diffuse.z;
    }
    const __m256 signBit = _mm256_set1_ps(-0.0f);
    __m256 n[3];
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const int k2 = (k + 2) % 3;
        n[k] = _mm256_sub_ps(_mm256_mul_ps(e1[k1], e2[k2]), _mm256_mul_ps(e2[k1], e1[k2]));
    }
    const __m256 length = _mm256_sqrt_ps(dot8(n, n));
    const __m256 lengthOk =
        _mm256_and_ps(_mm256_cmp_ps(length, zero, _CMP_GT_OQ),
                      _mm256_cmp_ps(length, _mm256_set1_ps(kInfinity), _CMP_LT_OQ));
    for (int k = 0; k < 3; ++k) {
        n[k] = _mm256_and_ps(_mm256_div_ps(n[k], length), lengthOk);
    }
    const __m256 flip = _mm256_and_ps(_mm256_cmp_ps(dot8(n, dir), zero, _CMP_GT_OQ), signBit);
    __m256 point[3], r[3];
    const glm::vec3 lightPosition = settings.light.position;
    for (int k = 0; k < 3; ++k) {
        n[k] = _mm256_xor_ps(n[k], flip);
        point[k] = _mm256_add_ps(o[k], _mm256_mul_ps(t, dir[k]));
        r[k] = _mm256_sub_ps(_mm256_set1_ps(lightPosition[k]), point[k]);
    }
    // lightAt: D = P * (cos / (4 pi |r|^2)) when |r|^2 > 0 and cos = dot(r / |r|, n) > 0.
    const __m256 distanceSquared = dot8(r, r);
    const __m256 distance = _mm256_sqrt_ps(distanceSquared);
    __m256 toLight[3];
    for (int k = 0; k < 3; ++k) {
        toLight[k] = _mm256_div_ps(r[k], distance);
    }
    const __m256 cosine = dot8(toLight, n);
    const __m256 lit = _mm256_and_ps(_mm256_cmp_ps(distanceSquared, zero, _CMP_GT_OQ),
                                     _mm256_cmp_ps(cosine, zero, _CMP_GT_OQ));
    const __m256 scale =
        _mm256_div_ps(cosine, _mm256_mul_ps(_mm256_set1_ps(kFourPi), distanceSquared));
    const glm::vec3 power = settings.light.power();
    __m256 direct[3];
    for (int k = 0; k < 3; ++k) {
        direct[k] = _mm256_and_ps(_mm256_mul_ps(_mm256_set1_ps(power[k]), scale), lit);
    }
    unsigned litLanes = static_cast<unsigned>(_mm256_movemask_ps(lit)) & hitLanes;
    if (settings.shadows && litLanes != 0) {
        alignas(32) float p[3][8], l[3][8], tMax[8];
        for (int k = 0; k < 3; ++k) {
            _mm256_store_ps(p[k], point[k]);
            _mm256_store_ps(l[k], toLight[k]);
        }
        const float epsilon = settings.shadowEpsilon;
        _mm256_store_ps(tMax, _mm256_sub_ps(distance, _mm256_set1_ps(epsilon)));
        Ray shadowRays[kPacketSize];
        int shadowLane[kPacketSize];
        int shadowCount = 0;
        for (unsigned m = litLanes; m != 0; m &= m - 1) {
            const int i = __builtin_ctz(m);
            shadowRays[shadowCount] = Ray{glm::vec3(p[0][i], p[1][i], p[2][i]),
                                          glm::vec3(l[0][i], l[1][i], l[2][i]), epsilon, tMax[i]};
            shadowLane[shadowCount++] = i;
        }
        bool occluded[kPacketSize];
        anyHit8(bvh, shadowRays, shadowCount, occluded);
        counts.shadow += static_cast<std::uint64_t>(shadowCount);
        for (int j = 0; j < shadowCount; ++j) {
            if (occluded[j]) {
                litLanes &= ~(1u << shadowLane[j]);
            }
        }
        alignas(32) int keep[8];
        for (int i = 0; i < 8; ++i) {
            keep[i] = (litLanes >> i) & 1u ? -1 : 0;
        }
        const __m256 keepMask =
            _mm256_castsi256_ps(_mm256_load_si256(reinterpret_cast<const __m256i*>(keep)));
        for (int k = 0; k < 3; ++k) {
            direct[k] = _mm256_and_ps(direct[k], keepMask);
        }
    }
    // labRadiance: R = rho * (D + N).
    const glm::vec3 indirect = settings.indirect3();
    alignas(32) float out[3][8];
    for (int k = 0; k < 3; ++k) {
        _mm256_store_ps(out[k],
                        _mm256_mul_ps(_mm256_load_ps(rho[k]),
                                      _mm256_add_ps(direct[k], _mm256_set1_ps(indirect[k]))));
    }
    for (int i = 0; i < count; ++i) {
        radiance[i] =
            (hitLanes >> i) & 1u ? glm::vec3(out[0][i], out[1][i], out[2][i]) : glm::vec3(0.0f);
    }
}

} // namespace

void shadeLab8(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const Ray* rays,
               int count, glm::vec3* radiance, RayCounts& counts) {
    Hit hits[kPacketSize];
    closestHit8(bvh, rays, count, hits);
    counts.primary += static_cast<std::uint64_t>(count);
    static const bool simd = bvhSimdSupported();
    // The gathers index triangles' floats with 32-bit integers.
    if (simd && scene.triangles.size() < (std::size_t{1} << 27)) {
        shadeLanesAvx2(scene, bvh, settings, rays, count, hits, radiance, counts);
    } else {
        shadeLanesScalar(scene, bvh, settings, rays, count, hits, radiance, counts);
    }
}

} // namespace raylab
