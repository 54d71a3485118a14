#include "render/film.h"

#include <algorithm>
#include <cmath>

namespace raylab {

void Film::reset(int width, int height, FilmLayers layers) {
    width_ = width;
    height_ = height;
    layers_ = layers;
    samples_ = 0;
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
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
    out.width = width_;
    out.height = height_;
    out.pixels.resize(sums_.size());
    const float s = scale();
    std::transform(sums_.begin(), sums_.end(), out.pixels.begin(),
                   [s](const glm::vec3& sum) { return sum * s; });
}

void Film::toDisplay(std::span<uint8_t> out, DisplayMode mode, float exposure,
                     PixelOrder order) const {
    toRgba8(sums_, scale(), mode, exposure, out, order);
}

NoiseEstimate Film::noise() const {
    NoiseEstimate estimate;
    if (squares_.empty() || samples_ < 2 || sums_.empty()) {
        return estimate;
    }
    const double n = samples_;
    double varianceOfMeans = 0.0;
    double total = 0.0;
    for (std::size_t i = 0; i < sums_.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double sum = sums_[i][c];
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
