#include "render/film.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

// Pixels converted to means at a time for the display bytes (on the stack).
constexpr std::size_t kDisplayChunk = 256;

} // namespace

glm::vec3 meanOf(const PixelSum& sum, uint32_t samples) {
    if (samples == 0) {
        return glm::vec3(0.0f);
    }
    const double scale = 1.0 / static_cast<double>(samples);
    return glm::vec3(static_cast<float>(fromFixed(sum.channel[0]) * scale),
                     static_cast<float>(fromFixed(sum.channel[1]) * scale),
                     static_cast<float>(fromFixed(sum.channel[2]) * scale));
}

void Film::reset(const FilmWindow& window, FilmLayers layers) {
    window_ = window;
    layers_ = layers;
    first_ = next_ = 0;
    const std::size_t pixels = static_cast<std::size_t>(std::max(window.width(), 0)) *
                               static_cast<std::size_t>(std::max(window.height(), 0));
    firsts_.resize(pixels);
    sums_.resize(pixels);
    squares_.resize(layers.moments ? pixels : 0);
    indirect_.resize(layers.indirect ? pixels : 0);
}

Framebuffer Film::mean() const {
    Framebuffer out;
    mean(out);
    return out;
}

void Film::mean(Framebuffer& out) const {
    out.width = width();
    out.height = height();
    out.pixels.resize(sums_.size());
    for (std::size_t i = 0; i < sums_.size(); ++i) {
        out.pixels[i] = mean(i);
    }
}

glm::vec3 Film::meanWith(std::size_t i, uint32_t samples) const {
    if (samples == 1) {
        const glm::vec3& r = firsts_[i];
        return glm::vec3(asStored(r.x), asStored(r.y), asStored(r.z));
    }
    return meanOf(sums_[i], samples);
}

PixelSum Film::sumOf(std::size_t i) const {
    if (samples() == 1) {
        PixelSum sum;
        sum.store(firsts_[i]);
        return sum;
    }
    return samples() == 0 ? PixelSum{} : sums_[i];
}

void Film::assign(std::span<const PixelSum> sums, uint32_t first, uint32_t next) {
    std::copy(sums.begin(), sums.end(), sums_.begin());
    first_ = first;
    next_ = next;
    if (samples() == 1) {
        for (std::size_t i = 0; i < sums_.size(); ++i) {
            firsts_[i] = meanOf(sums_[i], 1);
        }
    }
}

void Film::toDisplay(std::span<uint8_t> out, DisplayMode mode, float exposure,
                     PixelOrder order) const {
    display(0, sums_.size(), samples(), out, mode, exposure, order);
}

void Film::toDisplayCounting(std::size_t first, std::size_t count, uint32_t added,
                             std::span<uint8_t> out, DisplayMode mode, float exposure,
                             PixelOrder order) const {
    display(first, count, samples() + added, out, mode, exposure, order);
}

void Film::display(std::size_t first, std::size_t count, uint32_t samples, std::span<uint8_t> out,
                   DisplayMode mode, float exposure, PixelOrder order) const {
    glm::vec3 means[kDisplayChunk];
    for (std::size_t done = 0; done < count; done += kDisplayChunk) {
        const std::size_t n = std::min(kDisplayChunk, count - done);
        for (std::size_t i = 0; i < n; ++i) {
            means[i] = meanWith(first + done + i, samples);
        }
        toRgba8(std::span<const glm::vec3>(means, n), 1.0f, mode, exposure,
                out.subspan(4 * done, 4 * n), order);
    }
}

NoiseEstimate Film::noise() const {
    NoiseEstimate estimate;
    if (squares_.empty() || samples() < 2 || sums_.empty()) {
        return estimate;
    }
    const double n = samples();
    double varianceOfMeans = 0.0;
    double total = 0.0;
    for (std::size_t i = 0; i < sums_.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double sum = fromFixed(sumOf(i).channel[c]);
            const double variance = std::max(0.0, (squares_[i][c] - sum * sum / n) / (n - 1.0));
            varianceOfMeans += variance / n;
            total += sum / n;
        }
    }
    const double values = 3.0 * static_cast<double>(sums_.size());
    const double meanValue = total / values;
    if (!(meanValue > 0.0) || !std::isfinite(varianceOfMeans)) {
        return estimate;
    }
    estimate.known = true;
    estimate.relativeError = std::sqrt(varianceOfMeans / values) / meanValue;
    return estimate;
}

glm::vec3 Film::meanIndirect() const {
    double sum[3] = {0.0, 0.0, 0.0};
    double hits = 0.0;
    for (const glm::vec4& p : indirect_) {
        sum[0] += p.x;
        sum[1] += p.y;
        sum[2] += p.z;
        hits += p.w;
    }
    if (!(hits > 0.0)) {
        return glm::vec3(0.0f);
    }
    return glm::vec3(static_cast<float>(sum[0] / hits), static_cast<float>(sum[1] / hits),
                     static_cast<float>(sum[2] / hits));
}

} // namespace raylab
