#include "io/helper_path.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace raylab {

namespace {

constexpr const char* kHelperName = "raylab-import";

bool isExecutableFile(const std::filesystem::path& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

} // namespace

std::string findImportHelper(std::string& error) {
    if (const char* given = std::getenv("RAYLAB_IMPORT_HELPER"); given != nullptr) {
        if (isExecutableFile(given)) {
            return given;
        }
        error = std::string("the mesh importer '") + given +
                "' (RAYLAB_IMPORT_HELPER) is missing or not executable";
        return {};
    }
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) {
        error = "cannot find the mesh importer: /proc/self/exe is unreadable";
        return {};
    }
    const std::filesystem::path dir = self.parent_path();
    const std::filesystem::path candidates[] = {
        dir / kHelperName,                   // installed side by side
        dir / ".." / "import" / kHelperName, // build tree: src/cli, src/bench, src/viewer
        dir / ".." / ".." / "src" / "import" / kHelperName, // build tree: tests/<area>
    };
    for (const auto& candidate : candidates) {
        if (isExecutableFile(candidate)) {
            const std::filesystem::path clean = std::filesystem::weakly_canonical(candidate, ec);
            return ec ? candidate.string() : clean.string();
        }
    }
    error = std::string("cannot find the mesh importer '") + kHelperName + "' beside " +
            dir.string() + " (is it built and installed with the other programs?)";
    return {};
}

} // namespace raylab
