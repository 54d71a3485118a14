// The lab integrator's pictures do not change: 64-bit FNV-1a hashes of render()'s floats for
// several settings, taken from PFM files written by raylab-render before the Film and the
// integrators existed (commit 625e83c), whose bytes this build reproduces.

#include "core/bvh/bvh.h"
#include "core/cornell_box.h"
#include "core/render/renderer.h"

#include <cstdint>
#include <cstring>
#include <gtest/gtest.h>

namespace raylab {
namespace {

uint64_t fnv1a(const Framebuffer& image) {
    uint64_t hash = 0xcbf29ce484222325ULL;
    const auto* bytes = reinterpret_cast<const unsigned char*>(image.pixels.data());
    for (std::size_t i = 0; i < image.pixels.size() * sizeof(glm::vec3); ++i) {
        hash = (hash ^ bytes[i]) * 0x100000001b3ULL;
    }
    return hash;
}

TEST(LabGolden, TheLabsPicturesAreTheSameBytesAsBeforeTheFilm) {
    const Scene scene = makeCornellBox();
    const Bvh bvh = buildBvh(scene);
    struct Case {
        const char* what;
        RenderSettings settings;
        uint64_t hash;
    };
    std::vector<Case> cases;
    RenderSettings s;
    cases.push_back({"the lab's defaults", s, 0xd9a9d4f9015be020ULL});
    s.samplesPerPixel = 4;
    cases.push_back({"4 samples", s, 0x7e6cad461579a66fULL});
    s.samplesPerPixel = 3;
    s.shadowEpsilon = 0.0f;
    cases.push_back({"3 samples, epsilon 0", s, 0x16e6347142d7c7fcULL});
    s = RenderSettings();
    s.shadows = false;
    s.samplesPerPixel = 2;
    s.width = 320;
    s.height = 200;
    cases.push_back({"no shadows, 2 samples, 320 x 200", s, 0x579aef8e464599ceULL});
    s = RenderSettings();
    s.indirect = false;
    s.samplesPerPixel = 5;
    cases.push_back({"no indirect, 5 samples", s, 0xc6fead127b2db2b4ULL});
    for (const Case& c : cases) {
        EXPECT_EQ(fnv1a(render(scene, bvh, c.settings)), c.hash) << c.what;
    }
    // A light radius of 0 is the lab's point light: the same bytes.
    RenderSettings radiusZero;
    radiusZero.light.radius = 0.0f;
    EXPECT_EQ(fnv1a(render(scene, bvh, radiusZero)), cases[0].hash);
}

} // namespace
} // namespace raylab
