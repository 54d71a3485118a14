#include "split_view.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace raylab::viewer {

RenderSettings otherIntegrator(const RenderSettings& settings) {
    RenderSettings other = settings;
    other.integrator = settings.integrator == Integrator::Lab ? Integrator::Path : Integrator::Lab;
    return other;
}

RenderSettings splitCompare(const RenderSettings& live, const RenderSettings* snapshot) {
    if (snapshot == nullptr) {
        return otherIntegrator(live);
    }
    RenderSettings right = *snapshot;
    right.width = live.width;
    right.height = live.height;
    right.threads = live.threads;
    right.samplesPerPixel = live.samplesPerPixel;
    return right;
}

bool grabsDivider(double x, int width, float divider) {
    return std::abs(x - static_cast<double>(splitColumn(width, divider))) <= kDividerGrabPixels;
}

int splitColumn(int width, float divider) {
    const float column = std::round(std::clamp(divider, 0.0f, 1.0f) * static_cast<float>(width));
    return std::clamp(static_cast<int>(column), 0, width);
}

void composeSplit(std::span<const uint8_t> left, std::span<const uint8_t> right, int width,
                  int height, float divider, std::span<uint8_t> out) {
    const std::size_t row = 4 * static_cast<std::size_t>(width);
    const std::size_t split = 4 * static_cast<std::size_t>(splitColumn(width, divider));
    for (int y = 0; y < height; ++y) {
        const std::size_t at = static_cast<std::size_t>(y) * row;
        if (out.data() != left.data()) {
            std::memmove(out.data() + at, left.data() + at, split);
        }
        if (out.data() != right.data()) {
            std::memmove(out.data() + at + split, right.data() + at + split, row - split);
        }
    }
}

void composeSplit(Framebuffer& left, const Framebuffer& right, float divider) {
    const int split = splitColumn(left.width, divider);
    for (int y = 0; y < left.height; ++y) {
        for (int x = split; x < left.width; ++x) {
            left.at(x, y) = right.at(x, y);
        }
    }
}

} // namespace raylab::viewer
