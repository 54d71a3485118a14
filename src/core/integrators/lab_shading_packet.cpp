// shadeLab for a packet of camera rays: the camera rays, then the shadow rays of their lit hits,
// each traced as one packet (bvh_packet.h). The light model is lab_shading.cpp's stages; where the
// CPU has AVX2, the 8 lanes run those stages' operations side by side (shadeLanesAvx2), each
// rounded as the scalar stage rounds it (IEEE single precision, no contraction: core builds with
// -ffp-contract=off), so the radiance is bit for bit the scalar path's (tests/core checks it).
// Rays, hits and shadow rays stay in structure-of-arrays form (ray_packet.h) throughout.

#include "bvh/bvh_packet.h"
#include "integrators/lab_shading.h"
#include "integrators/lab_shading_stages.h"
#include "watertight_avx2.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab {

namespace {

// The layout computeNormals' triangle loads assume: v0, v1, v2 and the material are 10 floats,
// so 4 floats from v0, v1 or v2 stay inside the record, and the 4 from v2 end with the material.
static_assert(sizeof(Triangle) == 10 * sizeof(float) && offsetof(Triangle, v1) == 12 &&
              offsetof(Triangle, v2) == 24 && offsetof(Triangle, material) == 36);

constexpr float kFourPi = 12.566370614359172f; // as lab_shading.cpp

RAYLAB_AVX2 int laneCountAvx2(unsigned lanes) { return __builtin_popcount(lanes); }

void shadeLanesScalar(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                      const RayPacket& rays, const HitPacket& hits, RadiancePacket& radiance,
                      RayCounts& counts) {
    SurfacePoint surfaces[kPacketSize];
    glm::vec3 direct[kPacketSize];
    RayPacket shadowRays;
    unsigned hitLanes = 0;
    for (unsigned m = rays.lanes; m != 0; m &= m - 1) {
        const int i = __builtin_ctz(m);
        const Hit hit = hits.hit(i);
        if (!hit.found()) {
            continue;
        }
        hitLanes |= 1u << i;
        surfaces[i] = surfaceAt(scene, rays.ray(i), hit);
        const LightSample sample = lightAt(settings, surfaces[i].point, surfaces[i].facingNormal);
        direct[i] = sample.direct;
        if (sample.needsShadowRay) {
            shadowRays.set(i, sample.shadowRay);
        }
    }
    const unsigned occluded = anyHit8(bvh, shadowRays);
    counts.shadow += static_cast<std::uint64_t>(laneCount(shadowRays.lanes));
    for (int i = 0; i < kPacketSize; ++i) {
        glm::vec3 value(0.0f);
        if ((hitLanes >> i) & 1u) {
            value = labRadiance(settings, surfaces[i].rho,
                                (occluded >> i) & 1u ? glm::vec3(0.0f) : direct[i]);
        }
        for (int c = 0; c < 3; ++c) {
            radiance.value[c][i] = value[c];
        }
    }
}

RAYLAB_AVX2 inline __m256 dot8(const __m256 a[3], const __m256 b[3]) {
    // glm::dot: (a.x*b.x + a.y*b.y) + a.z*b.z
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(a[0], b[0]), _mm256_mul_ps(a[1], b[1])),
                         _mm256_mul_ps(a[2], b[2]));
}

// All ones in the lanes whose bit is set in `lanes`.
RAYLAB_AVX2 inline __m256 laneMask(unsigned lanes) {
    const __m256i bits = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
    return _mm256_castsi256_ps(_mm256_cmpeq_epi32(
        _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(lanes)), bits), bits));
}

// Row k of a packet's field of 3 rows (RayPacket::origin, ...). Loaded where used: GCC copies
// a loop of such loads into a local array through the stack.
RAYLAB_AVX2 inline __m256 load3(const float rows[3][kPacketSize], int k) {
    return _mm256_load_ps(rows[k]);
}

// rows = v. Written out: GCC turns a loop of such stores into a copy through the stack.
RAYLAB_AVX2 inline void store3(float rows[3][kPacketSize], const __m256 v[3]) {
    _mm256_store_ps(rows[0], v[0]);
    _mm256_store_ps(rows[1], v[1]);
    _mm256_store_ps(rows[2], v[2]);
}

// Every row = v.
RAYLAB_AVX2 inline void store3(float rows[3][kPacketSize], __m256 v) {
    const __m256 all[3] = {v, v, v};
    store3(rows, all);
}

// out[c] = float c of the 4 at rows[lane] + offset, for the 8 lanes: 8 unaligned 4-float loads
// and a transpose.
RAYLAB_AVX2 inline void loadColumns(const float* const rows[8], int offset, __m256 out[4]) {
    __m256 r[4];
    for (int i = 0; i < 4; ++i) {
        r[i] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(rows[i] + offset)),
                                    _mm_loadu_ps(rows[i + 4] + offset), 1);
    }
    const __m256 xy01 = _mm256_unpacklo_ps(r[0], r[1]);
    const __m256 zw01 = _mm256_unpackhi_ps(r[0], r[1]);
    const __m256 xy23 = _mm256_unpacklo_ps(r[2], r[3]);
    const __m256 zw23 = _mm256_unpackhi_ps(r[2], r[3]);
    out[0] = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(1, 0, 1, 0));
    out[1] = _mm256_shuffle_ps(xy01, xy23, _MM_SHUFFLE(3, 2, 3, 2));
    out[2] = _mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(1, 0, 1, 0));
    out[3] = _mm256_shuffle_ps(zw01, zw23, _MM_SHUFFLE(3, 2, 3, 2));
}

// The geometric normal and the material index of scene triangle index[lane], for the 8 lanes,
// computed as geometricNormal: normalize(cross(e1, e2)), (0, 0, 0) when the length is 0 or not
// finite.
RAYLAB_AVX2 inline void computeNormals(const Triangle* triangles, const uint32_t index[8],
                                       __m256 normal[3], __m256i& material) {
    const float* rows[kPacketSize];
    for (int i = 0; i < kPacketSize; ++i) {
        rows[i] = &triangles[index[i]].v0.x;
    }
    __m256 v0[4], v1[4], v2[4]; // v2[3] is the material index (the Triangle layout above)
    loadColumns(rows, 0, v0);
    loadColumns(rows, 3, v1);
    loadColumns(rows, 6, v2);
    __m256 e1[3], e2[3];
    for (int k = 0; k < 3; ++k) {
        e1[k] = _mm256_sub_ps(v1[k], v0[k]);
        e2[k] = _mm256_sub_ps(v2[k], v0[k]);
    }
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const int k2 = (k + 2) % 3;
        normal[k] = _mm256_sub_ps(_mm256_mul_ps(e1[k1], e2[k2]), _mm256_mul_ps(e2[k1], e1[k2]));
    }
    const __m256 length = _mm256_sqrt_ps(dot8(normal, normal));
    const __m256 lengthOk =
        _mm256_and_ps(_mm256_cmp_ps(length, _mm256_setzero_ps(), _CMP_GT_OQ),
                      _mm256_cmp_ps(length, _mm256_set1_ps(kInfinity), _CMP_LT_OQ));
    for (int k = 0; k < 3; ++k) {
        normal[k] = _mm256_and_ps(_mm256_div_ps(normal[k], length), lengthOk);
    }
    material = _mm256_castps_si256(v2[3]);
}

// rho[c][lane] = materials[material[lane]].diffuse[c]: a gather per channel, material *
// sizeof(Material) bytes from the first material's colour (material * sizeof(Material) / 4 must
// fit an int32: fewer than 178 million materials of 48 bytes). In callgrind, 3 gathers cost 62
// instructions a packet less than 24 scalar loads.
RAYLAB_AVX2 inline void gatherDiffuse(const std::vector<Material>& materials, __m256i material,
                                      __m256 rho[3]) {
    static_assert(sizeof(Material) % sizeof(float) == 0);
    const float* first = &materials.front().diffuse.x;
    const __m256i at =
        _mm256_mullo_epi32(material, _mm256_set1_epi32(sizeof(Material) / sizeof(float)));
    for (int k = 0; k < 3; ++k) {
        rho[k] = _mm256_i32gather_ps(first + k, at, sizeof(float));
    }
}

// surfaceAt, lightAt and labRadiance for 8 lanes up to the shadow test; lanes that missed (or
// hold no ray) give black.
RAYLAB_AVX2 void beginShadeAvx2(const Scene& scene, const RenderSettings& settings,
                                const RayPacket& rays, const HitPacket& hits,
                                ShadingBeforeShadow& stage, RayPacket& shadowRays,
                                RayCounts& counts) {
    // closestHit8 leaves kNoTriangle in the lanes without a ray or a hit.
    const __m256i triangle = _mm256_load_si256(reinterpret_cast<const __m256i*>(hits.triangle));
    const __m256i missed = _mm256_cmpeq_epi32(triangle, _mm256_set1_epi32(-1));
    const __m256 foundMask = _mm256_castsi256_ps(_mm256_xor_si256(missed, _mm256_set1_epi32(-1)));
    const unsigned hitLanes = static_cast<unsigned>(_mm256_movemask_ps(foundMask));
    const __m256 zero = _mm256_setzero_ps();
    shadowRays.lanes = 0;
    if (hitLanes == 0) {
        for (int c = 0; c < 3; ++c) {
            _mm256_store_ps(stage.lit[c], zero);
            _mm256_store_ps(stage.dark[c], zero);
        }
        return;
    }
    // Lanes without a hit read the first hit lane's triangle; their results are masked out.
    alignas(32) uint32_t index[kPacketSize];
    _mm256_store_si256(
        reinterpret_cast<__m256i*>(index),
        _mm256_blendv_epi8(
            triangle, _mm256_set1_epi32(static_cast<int>(hits.triangle[__builtin_ctz(hitLanes)])),
            missed));
    __m256 n[3];
    __m256i material;
    computeNormals(scene.triangles.data(), index, n, material);
    __m256 rho[3];
    gatherDiffuse(scene.materials, material, rho);
    const __m256 dir[3] = {load3(rays.direction, 0), load3(rays.direction, 1),
                           load3(rays.direction, 2)};
    const __m256 t = _mm256_load_ps(hits.t);
    const __m256 signBit = _mm256_set1_ps(-0.0f);
    const __m256 flip = _mm256_and_ps(_mm256_cmp_ps(dot8(n, dir), zero, _CMP_GT_OQ), signBit);
    __m256 point[3], r[3];
    const glm::vec3 lightPosition = settings.light.position;
    for (int k = 0; k < 3; ++k) {
        n[k] = _mm256_xor_ps(n[k], flip);
        point[k] = _mm256_add_ps(load3(rays.origin, k), _mm256_mul_ps(t, dir[k]));
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
    const __m256 keep = _mm256_and_ps(lit, foundMask); // the lit lanes
    const unsigned litLanes = static_cast<unsigned>(_mm256_movemask_ps(keep));
    if (settings.shadows && litLanes != 0) {
        // The shadow rays of the lit lanes, in their own lanes: eps < t < |r| - eps.
        store3(shadowRays.origin, point);
        store3(shadowRays.direction, toLight);
        const float epsilon = settings.shadowEpsilon;
        _mm256_store_ps(shadowRays.tMin, _mm256_set1_ps(epsilon));
        _mm256_store_ps(shadowRays.tMax, _mm256_sub_ps(distance, _mm256_set1_ps(epsilon)));
        shadowRays.lanes = litLanes;
        counts.shadow += static_cast<std::uint64_t>(__builtin_popcount(litLanes));
    }
    // labRadiance: R = rho * (D + N) when lit and unshadowed, rho * (0 + N) otherwise; black
    // where nothing was hit.
    const glm::vec3 indirect = settings.indirect3();
    for (int k = 0; k < 3; ++k) {
        const __m256 ambient = _mm256_set1_ps(indirect[k]);
        const __m256 direct = _mm256_and_ps(_mm256_mul_ps(_mm256_set1_ps(power[k]), scale), keep);
        _mm256_store_ps(
            stage.lit[k],
            _mm256_and_ps(_mm256_mul_ps(rho[k], _mm256_add_ps(direct, ambient)), foundMask));
        _mm256_store_ps(
            stage.dark[k],
            _mm256_and_ps(_mm256_mul_ps(rho[k], _mm256_add_ps(zero, ambient)), foundMask));
    }
}

RAYLAB_AVX2 void finishShadeAvx2(const ShadingBeforeShadow& stage, unsigned occluded,
                                 RadiancePacket& radiance) {
    const __m256 shadowed = laneMask(occluded);
    for (int k = 0; k < 3; ++k) {
        _mm256_store_ps(radiance.value[k],
                        _mm256_blendv_ps(_mm256_load_ps(stage.lit[k]),
                                         _mm256_load_ps(stage.dark[k]), shadowed));
    }
}

} // namespace

int laneCount(unsigned lanes) {
    static const bool simd = bvhSimdSupported();
    return simd ? laneCountAvx2(lanes) : __builtin_popcount(lanes);
}

// AVX2 code: callers check bvhSimdSupported() (lab_shading_stages.h).
RAYLAB_AVX2 void beginShade(const Scene& scene, const RenderSettings& settings,
                            const RayPacket& rays, const HitPacket& hits,
                            ShadingBeforeShadow& stage, RayPacket& shadowRays, RayCounts& counts) {
    beginShadeAvx2(scene, settings, rays, hits, stage, shadowRays, counts);
}

void finishShade(const ShadingBeforeShadow& stage, unsigned occluded, RadiancePacket& radiance) {
    finishShadeAvx2(stage, occluded, radiance);
}

namespace {

// surfaceAt, lightAt and labRadiance for 8 lanes; lanes that missed (or hold no ray) give black.
RAYLAB_AVX2 void shadeLanesAvx2(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                                const RayPacket& rays, const HitPacket& hits,
                                RadiancePacket& radiance, RayCounts& counts) {
    // Every lane kNoTriangle (no ray or no hit): black, without the shading's stores and loads.
    const __m256i triangle = _mm256_load_si256(reinterpret_cast<const __m256i*>(hits.triangle));
    if (_mm256_testc_si256(triangle, _mm256_set1_epi32(-1))) {
        store3(radiance.value, _mm256_setzero_ps());
        return;
    }
    ShadingBeforeShadow stage;
    RayPacket shadowRays{RayPacket::Unset{}}; // beginShadeAvx2 stores the lanes it sets
    beginShadeAvx2(scene, settings, rays, hits, stage, shadowRays, counts);
    finishShadeAvx2(stage, shadowRays.lanes != 0 ? anyHit8(bvh, shadowRays) : 0u, radiance);
}

} // namespace

void shadeLab8(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
               const RayPacket& rays, RadiancePacket& radiance, RayCounts& counts) {
    HitPacket hits{RayPacket::Unset{}};
    closestHit8(bvh, rays, hits);
    counts.primary += static_cast<std::uint64_t>(laneCount(rays.lanes));
    static const bool simd = bvhSimdSupported();
    if (simd) {
        shadeLanesAvx2(scene, bvh, settings, rays, hits, radiance, counts);
    } else {
        shadeLanesScalar(scene, bvh, settings, rays, hits, radiance, counts);
    }
}

void shadeLab8(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const Ray* rays,
               int count, glm::vec3* radiance, RayCounts& counts) {
    RayPacket packet;
    for (int i = 0; i < count; ++i) {
        packet.set(i, rays[i]);
    }
    RadiancePacket values;
    shadeLab8(scene, bvh, settings, packet, values, counts);
    for (int i = 0; i < count; ++i) {
        radiance[i] = glm::vec3(values.value[0][i], values.value[1][i], values.value[2][i]);
    }
}

} // namespace raylab
