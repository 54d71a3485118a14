#pragma once
// Which files are meshes raylab-import can read, by name: for the viewer's file browser, which
// lists folders and mesh files only. The list is the file extensions Debian's Assimp 5.2 reads
// (a test checks each against Assimp itself), less the generic ".xml".

#include <span>
#include <string_view>

namespace raylab {

// True when `fileName` ends in a mesh file extension ("bunny.PLY", "scene.mesh.xml"), in any
// case.
bool isMeshFileName(std::string_view fileName);

// The extensions, lower case with their dot (".ply", ".mesh.xml").
std::span<const std::string_view> meshFileExtensions();

} // namespace raylab
