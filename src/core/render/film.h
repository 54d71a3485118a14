#pragma once
// The film: the per-pixel sums of the samples of one picture and how many samples they hold, in
// the manner of pbrt's Film and yocto's trace_state. Every program that renders progressively
// (render(), raylab-render, raylab-bench, the viewer) keeps its samples here, so there is one
// rule for how samples accumulate, when a picture restarts, and how the mean and its display
// bytes are made from the sums.
//
// A film holds a range of sample indices, [firstSample(), nextSample()), of the pixels of a
// window of the image (the whole image unless the render is cropped). A pass (renderPass,
// renderer.h) writes sample nextSample() of every pixel of the window: the range's first sample
// is stored, whatever the sums held (so a restart needs no clearing), a later one is added.
//
// The sums of R are exact (exact_sum.h): the same samples give the same sums in any order and
// in any number of parts, so sample ranges rendered apart and added (raylab-merge) are the
// picture rendered in one go, bit for bit. The mean of a pixel is meanOf(sum, samples): the one
// division, shared by the mean image, the display bytes and the merge. A film holding one sample
// keeps it as floats instead (asStored(x) is what its sum would give back), so that one-sample
// pictures, the lab's and the viewer's while the camera moves, cost no conversion; the second
// sample turns them into sums.

#include "render/display_transform.h"
#include "render/exact_sum.h"
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

// The exact sums of one pixel's R, per channel.
struct PixelSum {
    FixedSum channel[3] = {0, 0, 0};

    void store(const glm::vec3& r) {
        for (int c = 0; c < 3; ++c) {
            channel[c] = toFixed(r[c]);
        }
    }
    void add(const glm::vec3& r) {
        for (int c = 0; c < 3; ++c) {
            channel[c] += toFixed(r[c]);
        }
    }
    void add(const PixelSum& other) {
        for (int c = 0; c < 3; ++c) {
            channel[c] += other.channel[c];
        }
    }
    bool operator==(const PixelSum&) const = default;
};

// The mean of `samples` samples whose sum is `sum` (0 with no sample): the one division.
glm::vec3 meanOf(const PixelSum& sum, uint32_t samples);

// The pixels [x0, x1) x [y0, y1) of an image: the part of it a film holds.
struct FilmWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool operator==(const FilmWindow&) const = default;
};

class Film {
public:
    Film() = default;
    Film(int width, int height, FilmLayers layers = {}) { reset(width, height, layers); }
    explicit Film(const FilmWindow& window, FilmLayers layers = {}) { reset(window, layers); }

    // A film of the whole width x height image with these layers and no samples. Keeps its
    // buffers when they fit.
    void reset(int width, int height, FilmLayers layers = {}) {
        reset(FilmWindow{0, 0, width, height}, layers);
    }
    // A film of a window of the image (a crop), with no samples.
    void reset(const FilmWindow& window, FilmLayers layers = {});
    // No samples: the next pass stores the range's first sample. The sums are left as they are
    // (that sample overwrites them), so a restart costs nothing.
    void restart() { next_ = first_; }
    // The range starts at sample `first` (a part of a render split by sample ranges): no samples,
    // and the next pass stores sample `first`.
    void startAt(uint32_t first) { first_ = next_ = first; }
    // The sums (and layers) already hold samples firstSample() .. next - 1, written by the
    // caller: the next pass writes sample `next`.
    void resume(uint32_t next) { next_ = next; }

    // The window's size and place in the image.
    int width() const { return window_.width(); }
    int height() const { return window_.height(); }
    const FilmWindow& window() const { return window_; }
    std::size_t pixelCount() const { return sums_.size(); }
    // The index into sums() etc. of image pixel (x, y), which must lie in the window.
    std::size_t indexOf(int x, int y) const {
        return static_cast<std::size_t>(y - window_.y0) * static_cast<std::size_t>(width()) +
               static_cast<std::size_t>(x - window_.x0);
    }
    FilmLayers layers() const { return layers_; }
    // The samples per pixel the sums hold.
    uint32_t samples() const { return next_ - first_; }
    // The index of the first sample the sums hold and of the sample the next pass writes.
    uint32_t firstSample() const { return first_; }
    uint32_t nextSample() const { return next_; }

    // How a pass writes sample nextSample() + k of a pixel (k counts from 0 within a pass of
    // several samples): the range's first is kept as floats, the second turns them and itself
    // into exact sums, later ones add to the sums.
    enum class Write { First, Second, Later };
    Write nextWrite(uint32_t k = 0) const {
        const uint32_t n = samples() + k;
        return n == 0 ? Write::First : (n == 1 ? Write::Second : Write::Later);
    }
    // Writes sample value r of pixel i as `how` says (nextWrite() of this pass). Passes write
    // different pixels from different threads.
    void write(std::size_t i, const glm::vec3& r, Write how) {
        switch (how) {
        case Write::First: firsts_[i] = r; break;
        case Write::Second:
            sums_[i].store(firsts_[i]);
            sums_[i].add(r);
            break;
        case Write::Later: sums_[i].add(r); break;
        }
    }
    // The exact sum of pixel i's samples.
    PixelSum sumOf(std::size_t i) const;
    // Makes the film hold the samples [first, next) whose exact sums are `sums` (pixelCount()
    // of them): a merge of parts.
    void assign(std::span<const PixelSum> sums, uint32_t first, uint32_t next);

    // For passes: the squares (float: they only estimate the noise) and the indirect layer
    // (empty when the layer is off; xyz: sum of N, w: samples that hit).
    std::span<glm::vec3> squares() { return squares_; }
    std::span<glm::vec4> indirect() { return indirect_; }
    std::span<const glm::vec3> squares() const { return squares_; }
    std::span<const glm::vec4> indirect() const { return indirect_; }
    // A pass that wrote samples nextSample() .. nextSample() + added - 1 of every pixel counts
    // them.
    void passFinished(uint32_t added = 1) { next_ += added; }

    // The mean of pixel i, meanOf(sumOf(i), samples()).
    glm::vec3 mean(std::size_t i) const { return meanWith(i, samples()); }
    // The mean image of the window.
    Framebuffer mean() const;
    void mean(Framebuffer& out) const;
    // Display bytes of the mean (toRgba8 of the means): out holds 4 * pixelCount() bytes.
    void toDisplay(std::span<uint8_t> out, DisplayMode mode, float exposure,
                   PixelOrder order = PixelOrder::Rgba) const;
    // For a pass, before it counts its `added` samples: the display bytes of pixels [first,
    // first + count) as toDisplay will write them once the pass is counted (out: 4 * count
    // bytes).
    void toDisplayCounting(std::size_t first, std::size_t count, uint32_t added,
                           std::span<uint8_t> out, DisplayMode mode, float exposure,
                           PixelOrder order) const;

    NoiseEstimate noise() const;
    // The mean of the path integrator's N over every sample that hit a surface, per channel;
    // 0 when the indirect layer is off or nothing was hit.
    glm::vec3 meanIndirect() const;

private:
    FilmWindow window_;
    FilmLayers layers_;
    uint32_t first_ = 0;
    uint32_t next_ = 0;
    // The mean of pixel i as if the film held `samples` samples.
    glm::vec3 meanWith(std::size_t i, uint32_t samples) const;
    void display(std::size_t first, std::size_t count, uint32_t samples, std::span<uint8_t> out,
                 DisplayMode mode, float exposure, PixelOrder order) const;

    std::vector<glm::vec3> firsts_;
    std::vector<PixelSum> sums_;
    std::vector<glm::vec3> squares_;
    std::vector<glm::vec4> indirect_;
};

} // namespace raylab
