#pragma once
// One fuzz input for the mesh loader: the first byte picks the file extension (so every importer
// we care about gets its share), the rest is the file. The loader must either succeed with only
// valid triangles and materials, or fail with one line that names the file. Shared by the libFuzzer
// target and the corpus replay test.

#include "io/mesh_loader.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace raylab::fuzz {

inline constexpr const char* kExtensions[] = {".obj", ".ply", ".gltf", ".glb", ".stl", ".off"};
inline constexpr std::size_t kExtensionCount = sizeof(kExtensions) / sizeof(kExtensions[0]);

// Returns an empty string when the loader behaved, otherwise what it did wrong.
inline std::string checkMeshLoader(const uint8_t* data, std::size_t size) {
    if (size == 0) {
        return {};
    }
    static const std::filesystem::path dir = [] {
        std::filesystem::path d =
            std::filesystem::temp_directory_path() / ("raylab-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    const std::string path =
        (dir / (std::string("input") + kExtensions[data[0] % kExtensionCount])).string();
    if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fwrite(data + 1, 1, size - 1, f);
        std::fclose(f);
    } else {
        return "cannot write the fuzz input file " + path;
    }

    Scene scene;
    MeshLoadReport report;
    std::string error;
    const bool ok = loadMesh(path, scene, report, error);
    std::remove(path.c_str());
    if (!ok) {
        if (error.empty() || error.find('\n') != std::string::npos ||
            error.find(path) == std::string::npos) {
            return "bad error line: '" + error + "'";
        }
        return {};
    }
    if (scene.triangles.empty() || scene.materials.empty()) {
        return "success with an empty scene";
    }
    for (const Triangle& t : scene.triangles) {
        if (!isValidTriangle(t) || t.material >= scene.materials.size()) {
            return "success with an invalid triangle";
        }
    }
    for (const Material& m : scene.materials) {
        for (int c = 0; c < 3; ++c) {
            if (!(m.diffuse[c] >= 0.0f && m.diffuse[c] <= 1.0f)) {
                return "diffuse colour outside [0, 1]";
            }
        }
    }
    return {};
}

} // namespace raylab::fuzz
