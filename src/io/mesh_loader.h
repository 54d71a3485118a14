#pragma once
// Turns mesh files (OBJ with MTL, PLY, glTF/GLB and whatever else Assimp reads) into a core Scene.

#include "core/scene.h"

#include <cstddef>
#include <memory>
#include <string>

namespace Assimp {
class Importer;
}

namespace raylab {

// What the loader skipped or had to guess; each count is reported as one warning line.
struct MeshLoadReport {
    std::size_t nonFiniteTriangles = 0;  // a NaN or infinite vertex coordinate
    std::size_t degenerateTriangles = 0; // zero area
    std::size_t badIndexFaces = 0;       // an index out of range
    std::size_t nonTriangleFaces = 0;    // points and lines, which have no surface
    bool missingMaterialLibrary = false; // e.g. an OBJ whose MTL file is missing
};

// Loads `path` into scene in this process, with Assimp. Only raylab-import (src/import) and
// tests call this; the programs read meshes through importMesh (mesh_import.h). Diffuse colour
// comes from the material (Kd / base colour), 0.75 grey where there is none. Returns false with a
// one-line error (naming the file) when the file is missing, unreadable, not a mesh, or has no
// valid triangle.
bool loadMesh(const std::string& path, Scene& scene, MeshLoadReport& report, std::string& error);

// loadMesh with a lifetime of its own for what Assimp built: Assimp's scene of the last read
// stays in memory until the reader reads again or is destroyed. raylab-import sends the
// triangles and then ends with _exit, so that the kernel takes Assimp's scene back at once
// instead of it being freed allocation by allocation (one per face) while the parent waits.
class MeshReader {
public:
    MeshReader();
    ~MeshReader();
    MeshReader(const MeshReader&) = delete;
    MeshReader& operator=(const MeshReader&) = delete;

    // As loadMesh.
    bool read(const std::string& path, Scene& scene, MeshLoadReport& report, std::string& error);

private:
    std::unique_ptr<Assimp::Importer> importer_;
};

// The report's warnings as lines ("bunny.ply: skipped 3 degenerate triangles"); empty when clean.
std::string describe(const MeshLoadReport& report, const std::string& path);

} // namespace raylab
