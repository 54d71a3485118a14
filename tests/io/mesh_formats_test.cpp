// isMeshFileName: the extensions Assimp reads, in any case, and nothing else; every extension on
// the list is one Debian's Assimp says it reads.

#include "io/mesh_formats.h"

#include <assimp/Importer.hpp>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace raylab {
namespace {

TEST(MeshFormats, MeshFilesAreKnownByTheirExtensionInAnyCase) {
    for (const char* name : {"bunny.ply", "dragon.PLY", "Sponza.gltf", "box.glb", "a.b.obj",
                             "robot.FBX", "scene.mesh.xml", "part.stl", "x.off"}) {
        EXPECT_TRUE(isMeshFileName(name)) << name;
    }
    for (const char* name : {"notes.txt", "picture.png", "settings.json", "ply", ".obj",
                             "config.xml", "obj.tar", "archive.zip", ""}) {
        EXPECT_FALSE(isMeshFileName(name)) << name;
    }
}

TEST(MeshFormats, EveryExtensionOnTheListIsOneAssimpReads) {
    Assimp::Importer importer;
    std::string list;
    importer.GetExtensionList(list); // "*.3d;*.3ds;..."
    std::istringstream parts(list);
    std::string pattern;
    int listedByAssimp = 0;
    int ours = 0;
    while (std::getline(parts, pattern, ';')) {
        const std::string extension = pattern.substr(1); // ".3d"
        ++listedByAssimp;
        if (isMeshFileName("file" + extension)) {
            ++ours;
        } else {
            EXPECT_EQ(extension, ".xml"); // the one left out on purpose
        }
    }
    EXPECT_GT(listedByAssimp, 50);
    EXPECT_EQ(ours, listedByAssimp - 1);
    // And nothing beyond Assimp's list.
    EXPECT_EQ(meshFileExtensions().size(), static_cast<std::size_t>(ours));
    for (const std::string_view extension : meshFileExtensions()) {
        EXPECT_TRUE(importer.IsExtensionSupported(std::string(extension))) << extension;
    }
}

} // namespace
} // namespace raylab
