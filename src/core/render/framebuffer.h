#pragma once
// A float RGB image, row-major from the top-left pixel, linear radiance (the lab's R).

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

namespace raylab {

struct Framebuffer {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels; // width * height, row y starts at y * width

    Framebuffer() = default;
    Framebuffer(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h) {}
    glm::vec3& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const glm::vec3& at(int x, int y) const {
        return pixels[static_cast<std::size_t>(y) * width + x];
    }
};

} // namespace raylab
