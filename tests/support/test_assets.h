#pragma once
// Where the tests find the shared meshes and the built executables.

#include <cstdlib>
#include <filesystem>
#include <string>

namespace raylab::test {

// The shared mesh folder (../shared/assets by default, or $RAYLAB_ASSET_DIR).
inline std::filesystem::path assetDir() {
    if (const char* env = std::getenv("RAYLAB_ASSET_DIR"); env && *env) {
        return env;
    }
    return RAYLAB_ASSET_DIR;
}

// A shared asset's path, or empty when the shared folder is absent (tests then GTEST_SKIP).
inline std::filesystem::path asset(const std::string& relative) {
    const std::filesystem::path p = assetDir() / relative;
    return std::filesystem::exists(p) ? p : std::filesystem::path();
}

inline std::filesystem::path sourceDir() { return RAYLAB_SOURCE_DIR; }
inline std::filesystem::path binaryDir() { return RAYLAB_BINARY_DIR; }

} // namespace raylab::test
