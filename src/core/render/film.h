#pragma once
// The film: the per-pixel sums of the samples of one picture and how many samples they hold, in
// the manner of pbrt's Film and yocto's trace_state. Every program that renders progressively
// (render(), raylab-render, raylab-bench, the viewer) keeps its samples here, so there is one
// rule for how samples accumulate, when a picture restarts, and how the mean and its display
// bytes are made from the sums.
//
// A pass (renderPass, renderer.h) writes sample samples() of every pixel: sample 0 is stored,
// whatever the sums held (so a restart needs no clearing), a later one is added. The mean of a
// pixel is sum * (1 / samples): the one division, shared by the mean image and display bytes.

#include "render/display_transform.h"
#include "render/framebuffer.h"

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

namespace raylab {

// What a film keeps besides the sums of R.
struct FilmLayers {
    bool moments = false;  // per-pixel sums of R squared: the noise estimate (noise())
    bool indirect = false; // per-pixel sums of the path integrator's N and its hit count

    bool operator==(const FilmLayers&) const = default;
};

// The image's remaining Monte Carlo noise, from the per-pixel second moments.
struct NoiseEstimate {
    bool known = false;         // needs moments and at least 2 samples
    double relativeError = 0.0; // sqrt(mean over pixels and channels of the variance of the
                                // mean) / (mean R over pixels and channels): comparable with
                                // relativeRmse (image_error.h) against a converged reference
};

class Film {
public:
    Film() = default;
    Film(int width, int height, FilmLayers layers = {}) { reset(width, height, layers); }

    // A film of this size and these layers, with no samples. Keeps its buffers when they fit.
    void reset(int width, int height, FilmLayers layers = {});
    // No samples: the next pass stores sample 0. The sums are left as they are (sample 0
    // overwrites them), so a restart costs nothing.
    void restart() { samples_ = 0; }
    // The sums (and layers) already hold samples 0 .. samples - 1, written by the caller: the next
    // pass writes sample `samples`.
    void resume(uint32_t samples) { samples_ = samples; }

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t pixelCount() const { return sums_.size(); }
    FilmLayers layers() const { return layers_; }
    // The samples per pixel the sums hold: the index of the sample the next pass writes.
    uint32_t samples() const { return samples_; }

    // For passes: the sums (width * height, row-major from the top), the squares and the
    // indirect layer (empty when the layer is off; xyz: sum of N, w: samples that hit).
    std::span<glm::vec3> sums() { return sums_; }
    std::span<glm::vec3> squares() { return squares_; }
    std::span<glm::vec4> indirect() { return indirect_; }
    std::span<const glm::vec3> sums() const { return sums_; }
    std::span<const glm::vec3> squares() const { return squares_; }
    std::span<const glm::vec4> indirect() const { return indirect_; }
    // A pass that wrote sample samples() of every pixel counts it.
    void passFinished() { ++samples_; }

    // 1 / samples (0 with no sample): the factor that turns sums into means.
    float scale() const { return samples_ == 0 ? 0.0f : 1.0f / static_cast<float>(samples_); }
    // The mean image, sum * scale() per pixel.
    Framebuffer mean() const;
    void mean(Framebuffer& out) const;
    // Display bytes of the mean (toRgba8 with scale()): out holds 4 * pixelCount() bytes.
    void toDisplay(std::span<uint8_t> out, DisplayMode mode, float exposure,
                   PixelOrder order = PixelOrder::Rgba) const;

    NoiseEstimate noise() const;
    // The mean of the path integrator's N over every sample that hit a surface, per channel;
    // 0 when the indirect layer is off or nothing was hit.
    glm::vec3 meanIndirect() const;

private:
    int width_ = 0;
    int height_ = 0;
    FilmLayers layers_;
    uint32_t samples_ = 0;
    std::vector<glm::vec3> sums_;
    std::vector<glm::vec3> squares_;
    std::vector<glm::vec4> indirect_;
};

} // namespace raylab
