#include "io/mesh_formats.h"

#include "io/text_util.h"

#include <algorithm>
#include <array>
#include <string>

namespace raylab {

namespace {

// Assimp::Importer::GetExtensionList() of Debian's Assimp 5.2, without "xml" (too generic: only
// Ogre's ".mesh.xml" is kept).
constexpr std::array<std::string_view, 69> kMeshExtensions = {
    ".3d",     ".3ds",     ".3mf",       ".ac",      ".ac3d", ".acc",  ".amf",  ".ase",
    ".ask",    ".assbin",  ".b3d",       ".blend",   ".bsp",  ".bvh",  ".cob",  ".csm",
    ".dae",    ".dxf",     ".enff",      ".fbx",     ".glb",  ".gltf", ".hmp",  ".ifc",
    ".ifczip", ".iqm",     ".irr",       ".irrmesh", ".lwo",  ".lws",  ".lxo",  ".md2",
    ".md3",    ".md5anim", ".md5camera", ".md5mesh", ".mdc",  ".mdl",  ".mesh", ".mesh.xml",
    ".mot",    ".ms3d",    ".ndo",       ".nff",     ".obj",  ".off",  ".ogex", ".pk3",
    ".ply",    ".pmx",     ".prj",       ".q3o",     ".q3s",  ".raw",  ".scn",  ".sib",
    ".smd",    ".step",    ".stl",       ".stp",     ".ter",  ".uc",   ".vta",  ".x",
    ".x3d",    ".x3db",    ".xgl",       ".zae",     ".zgl"};

} // namespace

std::span<const std::string_view> meshFileExtensions() { return kMeshExtensions; }

bool isMeshFileName(std::string_view fileName) {
    const std::string lower = lowerCase(std::string(fileName));
    return std::any_of(kMeshExtensions.begin(), kMeshExtensions.end(), [&](std::string_view e) {
        return lower.size() > e.size() && lower.compare(lower.size() - e.size(), e.size(), e) == 0;
    });
}

} // namespace raylab
