#pragma once
// Mesh files read where they cannot hurt the session: in raylab-import, a helper process with a
// memory limit, a time limit and a syscall filter (src/import). The parent only spawns it,
// reads its answer from a pipe and validates it (import_stream.h).

#include "core/scene.h"
#include "io/import_limits.h"
#include "io/mesh_loader.h"

#include <functional>
#include <string>
#include <vector>

namespace raylab {

// How the caller follows and stops a running import. Both are called on the importing thread
// about every 20 ms; both may be empty.
struct ImportControl {
    std::function<bool()> cancelled;             // true: kill the helper, fail with "cancelled"
    std::function<void(double seconds)> running; // the time since the helper started
};

// Reads `path` in raylab-import. Returns true with scene (its name set to path), report and the
// importer's warning lines; or false with one line in `error` that names the file and says what
// happened: the importer's own reason, "the importer crashed (SIGSEGV)", "needed more than 4 GiB",
// "took longer than 60 s", "cancelled", a malformed answer, or a missing helper. On failure
// scene and report are untouched.
bool importMesh(const std::string& path, const ImportLimits& limits, Scene& scene,
                MeshLoadReport& report, std::vector<std::string>& warnings, std::string& error,
                const ImportControl& control = {});

// "cornell" is the built-in lab box; anything else is a mesh path read with importMesh.
// `warnings` gets describe(report) and the importer's warning lines, one per line.
bool loadScene(const std::string& nameOrPath, const ImportLimits& limits, Scene& scene,
               std::string& warnings, std::string& error, const ImportControl& control = {});

} // namespace raylab
