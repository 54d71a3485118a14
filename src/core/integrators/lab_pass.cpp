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

// Writes lanes [0, count) of `radiance` to the film's pixels row .. row + count - 1.
inline void write(const RadiancePacket& radiance, int count, Film::Write how, std::size_t row,
                  Film& film) {
    if (how == Film::Write::Later && count == kPacketSize) {
        film.addEight(row, radiance.value[0], radiance.value[1], radiance.value[2]);
        return;
    }
    for (int i = 0; i < count; ++i) {
        film.write(row + static_cast<std::size_t>(i),
                   glm::vec3(radiance.value[0][i], radiance.value[1][i], radiance.value[2][i]),
                   how);
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
    const std::span<glm::vec3> squares = film.squares();
    const PrimaryRays rays(settings.camera, settings.width, settings.height);
    static const bool simd = bvhSimdSupported();

    return forEachPassTile(
        settings, film, counts, options,
        [&](const TileRect& tile, const PassSample& sample, RayCounts& tileCounts) {
            const uint32_t sampleIndex = sample.index;
            const uint32_t sampleSeed = hash32(sampleIndex);
            const bool first = sample.how == Film::Write::First;
            // Blocks of up to 8 x 8 pixels: each row of a block is one packet (shadeLabBlock).
            RayPacket packets[kPacketSize];
            RadiancePacket radiance[kPacketSize];
            uint32_t rowSeeds[kPacketSize];
            float px[kPacketSize];
            float py[kPacketSize];
            TileCarry carry; // from block to block of the tile (shadeLabBlock)
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
                                  tileCounts, BlockTracing::ForScene, &carry);
                    for (int r = 0; r < rows; ++r) {
                        const std::size_t row = film.indexOf(x0, y0 + r);
                        write(radiance[r], count, sample.how, row, film);
                        if (!squares.empty()) {
                            storeOrAddSquares(radiance[r], count, first, &squares[row]);
                        }
                    }
                }
            }
        });
}

} // namespace raylab
