#include "integrators/lab_pass.h"

#include "bvh/bvh_packet.h"
#include "camera.h"
#include "render/pass_tiles.h"
#include "sampling/hash.h"
#include "watertight_avx2.h"

#include <algorithm>
#include <atomic>
#include <cassert>

namespace raylab {

namespace {

// The image points of sample `sampleIndex` of pixels (x0 + i, y), i < count: pixel centres for
// sample 0, else samplePixelOffset's jitter (with its row and sample hashes given as rowSeed).
void samplePoints(int x0, int y, int count, uint32_t sampleIndex, uint32_t rowSeed, float* px,
                  float* py) {
    for (int i = 0; i < count; ++i) {
        const int x = x0 + i;
        PixelOffset offset{0.5f, 0.5f};
        if (sampleIndex != 0) {
            const uint32_t seed = hash32(static_cast<uint32_t>(x) ^ rowSeed);
            offset = {unitFloat(seed), unitFloat(hash32(seed ^ 0x9e3779b9U))};
        }
        px[i] = static_cast<float>(x) + offset.dx;
        py[i] = static_cast<float>(y) + offset.dy;
    }
}

// hash32 (sampling.h) on 8 lanes.
RAYLAB_AVX2 inline __m256i hash32x8(__m256i x) {
    x = _mm256_xor_si256(x, _mm256_srli_epi32(x, 16));
    x = _mm256_mullo_epi32(x, _mm256_set1_epi32(0x7feb352d));
    x = _mm256_xor_si256(x, _mm256_srli_epi32(x, 15));
    x = _mm256_mullo_epi32(x, _mm256_set1_epi32(static_cast<int>(0x846ca68bU)));
    return _mm256_xor_si256(x, _mm256_srli_epi32(x, 16));
}

// unitFloat (sampling.h) on 8 lanes.
RAYLAB_AVX2 inline __m256 unitFloat8(__m256i bits) {
    return _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_srli_epi32(bits, 8)),
                         _mm256_set1_ps(0x1.0p-24f));
}

// samplePoints for 8 pixels at once: the same integer hash and the same float operations, so
// the points are bit for bit samplePoints'.
RAYLAB_AVX2 void samplePoints8(int x0, int y, uint32_t sampleIndex, uint32_t rowSeed, float* px,
                               float* py) {
    const __m256i x =
        _mm256_add_epi32(_mm256_set1_epi32(x0), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    __m256 dx = _mm256_set1_ps(0.5f);
    __m256 dy = _mm256_set1_ps(0.5f);
    if (sampleIndex != 0) {
        const __m256i seed =
            hash32x8(_mm256_xor_si256(x, _mm256_set1_epi32(static_cast<int>(rowSeed))));
        dx = unitFloat8(seed);
        dy = unitFloat8(
            hash32x8(_mm256_xor_si256(seed, _mm256_set1_epi32(static_cast<int>(0x9e3779b9U)))));
    }
    _mm256_storeu_ps(px, _mm256_add_ps(_mm256_cvtepi32_ps(x), dx));
    _mm256_storeu_ps(py, _mm256_add_ps(_mm256_set1_ps(static_cast<float>(y)), dy));
}

// The 8 lanes of `radiance` as 24 floats r0 g0 b0 r1 ... b7 in out[0..2]. Within each 128-bit
// half (4 pixels), each output quarter is a blend of the channels permuted so that every value
// sits in its output position: r0 g0 b0 r1 | g1 b1 r2 g2 | b2 r3 g3 b3.
RAYLAB_AVX2 inline void interleave8(const RadiancePacket& radiance, __m256 out[3]) {
    const __m256 r = _mm256_permute_ps(_mm256_load_ps(radiance.value[0]), _MM_SHUFFLE(1, 2, 3, 0));
    const __m256 g = _mm256_permute_ps(_mm256_load_ps(radiance.value[1]), _MM_SHUFFLE(2, 3, 0, 1));
    const __m256 b = _mm256_permute_ps(_mm256_load_ps(radiance.value[2]), _MM_SHUFFLE(3, 0, 1, 2));
    const __m256 first = _mm256_blend_ps(_mm256_blend_ps(r, g, 0x22), b, 0x44);  // r g b r
    const __m256 second = _mm256_blend_ps(_mm256_blend_ps(g, r, 0x44), b, 0x22); // g b r g
    const __m256 third = _mm256_blend_ps(_mm256_blend_ps(b, r, 0x22), g, 0x44);  // b r g b
    out[0] = _mm256_permute2f128_ps(first, second, 0x20); // pixels 0, 1, 2 (r g)
    out[1] = _mm256_permute2f128_ps(third, first, 0x30);  // pixels 2 (b), 3, 4, 5 (r)
    out[2] = _mm256_permute2f128_ps(second, third, 0x31); // pixels 5 (g b), 6, 7
}

// storeOrAdd for a full packet: the same float additions, 8 pixels at a time.
RAYLAB_AVX2 void storeOrAdd8(const RadiancePacket& radiance, bool first, glm::vec3* row) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    float* out = &row[0].x;
    __m256 values[3];
    interleave8(radiance, values);
    for (int k = 0; k < 3; ++k) {
        const __m256 sum =
            first ? values[k] : _mm256_add_ps(_mm256_loadu_ps(out + 8 * k), values[k]);
        _mm256_storeu_ps(out + 8 * k, sum);
    }
}

// Writes lanes [0, count) of `radiance` to row[0, count): stored when `first`, else added.
inline void storeOrAdd(const RadiancePacket& radiance, int count, bool first, glm::vec3* row) {
    if (first) {
        for (int i = 0; i < count; ++i) {
            row[i] = glm::vec3(radiance.value[0][i], radiance.value[1][i], radiance.value[2][i]);
        }
        return;
    }
    for (int i = 0; i < count; ++i) {
        row[i] += glm::vec3(radiance.value[0][i], radiance.value[1][i], radiance.value[2][i]);
    }
}

// storeOrAdd of the squares of the lanes (the film's moments).
inline void storeOrAddSquares(const RadiancePacket& radiance, int count, bool first,
                              glm::vec3* row) {
    for (int i = 0; i < count; ++i) {
        const glm::vec3 v(radiance.value[0][i], radiance.value[1][i], radiance.value[2][i]);
        row[i] = first ? v * v : row[i] + v * v;
    }
}

} // namespace

bool labPass(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Film& film,
             RayCounts* counts, const PassOptions& options) {
    const int width = settings.width;
    const uint32_t sampleIndex = film.samples();
    const std::span<glm::vec3> sums = film.sums();
    const std::span<glm::vec3> squares = film.squares();
    const PrimaryRays rays(settings.camera, width, settings.height);
    const uint32_t sampleSeed = hash32(sampleIndex);
    static const bool simd = bvhSimdSupported();

    return forEachPassTile(
        settings, film, counts, options, [&](const TileRect& tile, RayCounts& tileCounts) {
            // Blocks of up to 8 x 8 pixels: each row of a block is one packet (shadeLabBlock).
            RayPacket packets[kPacketSize];
            RadiancePacket radiance[kPacketSize];
            uint32_t rowSeeds[kPacketSize];
            float px[kPacketSize];
            float py[kPacketSize];
            for (int y0 = tile.y0; y0 < tile.y1; y0 += kPacketSize) {
                const int rows = std::min(kPacketSize, tile.y1 - y0);
                for (int r = 0; r < rows; ++r) {
                    // samplePixelOffset's hash with its row and sample parts hoisted out of the
                    // pixels.
                    rowSeeds[r] = hash32(static_cast<uint32_t>(y0 + r) ^ sampleSeed);
                }
                for (int x0 = tile.x0; x0 < tile.x1; x0 += kPacketSize) {
                    const int count = std::min(kPacketSize, tile.x1 - x0);
                    for (int r = 0; r < rows; ++r) {
                        if (simd && count == kPacketSize) {
                            samplePoints8(x0, y0 + r, sampleIndex, rowSeeds[r], px, py);
                        } else {
                            samplePoints(x0, y0 + r, count, sampleIndex, rowSeeds[r], px, py);
                        }
                        rays.through8(px, py, count, packets[r]);
                    }
                    // Sample 0 is at the pixel centres; later samples anywhere in the pixels.
                    const float inset = sampleIndex == 0 ? 0.5f : 0.0f;
                    const ImageRect rect{static_cast<float>(x0) + inset,
                                         static_cast<float>(y0) + inset,
                                         static_cast<float>(x0 + count) - inset,
                                         static_cast<float>(y0 + rows) - inset};
                    shadeLabBlock(scene, bvh, settings, rays, rect, packets, rows, radiance,
                                  tileCounts);
                    for (int r = 0; r < rows; ++r) {
                        const std::size_t first = static_cast<std::size_t>(y0 + r) * width + x0;
                        if (simd && count == kPacketSize) {
                            storeOrAdd8(radiance[r], sampleIndex == 0, &sums[first]);
                        } else {
                            storeOrAdd(radiance[r], count, sampleIndex == 0, &sums[first]);
                        }
                        if (!squares.empty()) {
                            storeOrAddSquares(radiance[r], count, sampleIndex == 0,
                                              &squares[first]);
                        }
                    }
                }
            }
        });
}

} // namespace raylab
