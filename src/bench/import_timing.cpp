// raylab-import-timing: one mesh load, timed, in a fresh process, as raylab-render and
// raylab-bench load at start. scripts/bench_import.sh runs it many times, alternating the ways.
//   raylab-import-timing in-process|helper MESH
// in-process: loadMesh, Assimp in this process (how the programs read meshes before the helper);
// helper: importMesh, through raylab-import (how they read them now). Prints the milliseconds
// from the call to the scene in memory, then the triangle count; exit 1 with the error line when
// the load fails.

#include "io/import_limits.h"
#include "io/mesh_import.h"
#include "io/mesh_loader.h"

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    const std::string way = argc == 3 ? argv[1] : "";
    if (way != "in-process" && way != "helper") {
        std::fprintf(stderr, "usage: raylab-import-timing in-process|helper MESH\n");
        return 2;
    }
    const std::string path = argv[2];
    raylab::Scene scene;
    raylab::MeshLoadReport report;
    std::vector<std::string> warnings;
    std::string error;
    const auto start = std::chrono::steady_clock::now();
    const bool ok = way == "in-process" ? raylab::loadMesh(path, scene, report, error)
                                        : raylab::importMesh(path, raylab::ImportLimits{}, scene,
                                                             report, warnings, error);
    const auto end = std::chrono::steady_clock::now();
    if (!ok) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
    }
    std::printf("%.3f %zu\n", std::chrono::duration<double, std::milli>(end - start).count(),
                scene.triangles.size());
    return 0;
}
