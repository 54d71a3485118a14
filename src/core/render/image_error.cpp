#include "render/image_error.h"

#include <cmath>
#include <limits>

namespace raylab {

double relativeRmse(const Framebuffer& image, const Framebuffer& reference) {
    const double inf = std::numeric_limits<double>::infinity();
    if (image.pixels.size() != reference.pixels.size() || reference.pixels.empty()) {
        return inf;
    }
    double squaredError = 0.0;
    double total = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double difference =
                static_cast<double>(image.pixels[i][c]) - reference.pixels[i][c];
            squaredError += difference * difference;
            total += reference.pixels[i][c];
        }
    }
    const double values = 3.0 * static_cast<double>(image.pixels.size());
    const double meanReference = total / values;
    if (!(meanReference > 0.0) || !std::isfinite(squaredError)) {
        return inf;
    }
    return std::sqrt(squaredError / values) / meanReference;
}

} // namespace raylab
