// The mesh loader on the shared real meshes (counts from ../shared/assets/SOURCES.md) and on
// generated bad files: every bad file either fails with one line naming it, or loads with what
// could be skipped counted in the report.

#include "core/cornell_box.h"
#include "io/mesh_import.h"
#include "io/mesh_loader.h"
#include "test_assets.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

namespace raylab {
namespace {

namespace fs = std::filesystem;

class TempDir {
public:
    TempDir() {
        path_ = fs::temp_directory_path() /
                ("raylab-mesh-test-" +
                 std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    std::string write(const std::string& name, const std::string& bytes) const {
        const fs::path p = path_ / name;
        std::ofstream(p, std::ios::binary) << bytes;
        return p.string();
    }

private:
    fs::path path_;
};

struct Loaded {
    bool ok = false;
    Scene scene;
    MeshLoadReport report;
    std::string error;
};

Loaded load(const std::string& path) {
    Loaded l;
    l.ok = loadMesh(path, l.scene, l.report, l.error);
    return l;
}

// A failure must be one line that names the file.
void expectCleanFailure(const Loaded& l, const std::string& path) {
    EXPECT_FALSE(l.ok);
    EXPECT_FALSE(l.error.empty());
    EXPECT_EQ(l.error.find('\n'), std::string::npos) << l.error;
    EXPECT_NE(l.error.find(path), std::string::npos) << l.error;
}

std::size_t skipped(const MeshLoadReport& r) {
    return r.nonFiniteTriangles + r.degenerateTriangles + r.badIndexFaces + r.nonTriangleFaces;
}

const std::string kPlyHeader3 = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n";

// ---- the shared assets ----------------------------------------------------------------------

void expectTriangleTotal(const std::string& relative, std::size_t total) {
    const fs::path p = test::asset(relative);
    if (p.empty()) {
        GTEST_SKIP() << "shared asset " << relative << " not found";
    }
    const Loaded l = load(p.string());
    ASSERT_TRUE(l.ok) << l.error;
    // Every face of the file is either loaded or counted as skipped.
    EXPECT_EQ(l.scene.triangles.size() + skipped(l.report), total);
    EXPECT_EQ(l.report.nonFiniteTriangles, 0u);
    EXPECT_EQ(l.report.badIndexFaces, 0u);
    EXPECT_FALSE(l.report.missingMaterialLibrary);
    // Degenerate faces are rare in these scans and exports.
    EXPECT_LT(l.report.degenerateTriangles * 1000, total);
}

TEST(MeshLoaderAssets, CornellObjHas36TrianglesAndItsMaterials) {
    const fs::path p = test::asset("cornell/CornellBox-Original.obj");
    if (p.empty()) {
        GTEST_SKIP() << "shared assets not found";
    }
    const Loaded l = load(p.string());
    ASSERT_TRUE(l.ok) << l.error;
    // 18 quads, including the two coincident "bottom face" quads of the blocks: all kept.
    EXPECT_EQ(l.scene.triangles.size(), 36u);
    EXPECT_EQ(skipped(l.report), 0u);
    EXPECT_FALSE(l.report.missingMaterialLibrary);
    // Kd from the MTL, by material name.
    bool sawLeft = false, sawRight = false;
    for (const Material& m : l.scene.materials) {
        if (m.name == "leftWall") {
            sawLeft = true;
            EXPECT_FLOAT_EQ(m.diffuse.x, 0.63f);
            EXPECT_FLOAT_EQ(m.diffuse.y, 0.065f);
            EXPECT_FLOAT_EQ(m.diffuse.z, 0.05f);
        }
        if (m.name == "rightWall") {
            sawRight = true;
            EXPECT_FLOAT_EQ(m.diffuse.y, 0.45f);
        }
    }
    EXPECT_TRUE(sawLeft);
    EXPECT_TRUE(sawRight);
    // Negative (relative) indices resolved: the bounds are the file's.
    const Aabb b = l.scene.bounds();
    EXPECT_FLOAT_EQ(b.lower.x, -1.02f);
    EXPECT_FLOAT_EQ(b.upper.y, 1.99f);
    EXPECT_FLOAT_EQ(b.lower.z, -1.04f);
    // The coincident quad quirk: some triangle appears twice.
    std::size_t duplicates = 0;
    for (std::size_t i = 0; i < l.scene.triangles.size(); ++i) {
        for (std::size_t j = i + 1; j < l.scene.triangles.size(); ++j) {
            const Triangle& a = l.scene.triangles[i];
            const Triangle& c = l.scene.triangles[j];
            duplicates += (a.v0 == c.v0 && a.v1 == c.v1 && a.v2 == c.v2) ? 1 : 0;
        }
    }
    EXPECT_GE(duplicates, 2u);
}

TEST(MeshLoaderAssets, GltfBoxHas12TrianglesWithBaseColour) {
    const fs::path p = test::asset("gltf/Box-embedded.gltf");
    if (p.empty()) {
        GTEST_SKIP() << "shared assets not found";
    }
    const Loaded l = load(p.string());
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_EQ(l.scene.triangles.size(), 12u);
    const Material& m = l.scene.materials.at(l.scene.triangles[0].material);
    EXPECT_NEAR(m.diffuse.x, 0.8f, 1e-6f);
    EXPECT_EQ(m.diffuse.y, 0.0f);
    EXPECT_EQ(m.diffuse.z, 0.0f);
}

TEST(MeshLoaderAssets, BunnyFull) { expectTriangleTotal("bunny/bun_zipper.ply", 69451); }
TEST(MeshLoaderAssets, BunnyRes2) { expectTriangleTotal("bunny/bun_zipper_res2.ply", 16301); }
TEST(MeshLoaderAssets, DragonRes2) { expectTriangleTotal("dragon/dragon_vrip_res2.ply", 202520); }
TEST(MeshLoaderAssets, DragonFull) { expectTriangleTotal("dragon/dragon_vrip.ply", 871414); }
TEST(MeshLoaderAssets, Sponza) { expectTriangleTotal("sponza/sponza.obj", 66454); }

TEST(MeshLoaderAssets, BunnyBoundsAndGrey) {
    const fs::path p = test::asset("bunny/bun_zipper.ply");
    if (p.empty()) {
        GTEST_SKIP() << "shared assets not found";
    }
    const Loaded l = load(p.string());
    ASSERT_TRUE(l.ok) << l.error;
    const Aabb b = l.scene.bounds();
    EXPECT_NEAR(b.lower.x, -0.0947f, 1e-4f);
    EXPECT_NEAR(b.upper.y, 0.1873f, 1e-4f);
    EXPECT_NEAR(b.upper.z, 0.0588f, 1e-4f);
    // PLY has no materials: 0.75 grey.
    for (const Material& m : l.scene.materials) {
        EXPECT_EQ(m.diffuse, glm::vec3(0.75f));
    }
}

TEST(MeshLoader, CornellNameIsTheBuiltInBox) {
    Scene scene;
    std::string warnings, error;
    ASSERT_TRUE(loadScene("cornell", ImportLimits{}, scene, warnings, error)) << error;
    const Scene box = makeCornellBox();
    ASSERT_EQ(scene.triangles.size(), 30u);
    for (std::size_t i = 0; i < box.triangles.size(); ++i) {
        EXPECT_EQ(scene.triangles[i].v0, box.triangles[i].v0);
        EXPECT_EQ(scene.triangles[i].material, box.triangles[i].material);
    }
    EXPECT_EQ(warnings, "");
}

// ---- generated files that load ---------------------------------------------------------------

TEST(MeshLoader, GltfNodeTransformAndBaseColourApply) {
    TempDir dir;
    // One triangle (0,0,0) (1,0,0) (0,1,0) under a node translated by (10, 0, 0); base colour
    // (0.2, 0.4, 0.6). The buffer is the 36 bytes of positions and 3 uint16 indices (+2 padding),
    // base64-encoded.
    const std::string gltf =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
        R"("nodes":[{"mesh":0,"translation":[10,0,0]}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],)"
        R"("materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.4,0.6,1]}}],)"
        R"("buffers":[{"byteLength":44,"uri":"data:application/octet-stream;base64,)"
        R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],)"
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
        R"({"buffer":0,"byteOffset":36,"byteLength":6}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":3,)"
        R"("type":"SCALAR"}]})";
    const Loaded l = load(dir.write("tri.gltf", gltf));
    ASSERT_TRUE(l.ok) << l.error;
    ASSERT_EQ(l.scene.triangles.size(), 1u);
    const Aabb b = l.scene.bounds();
    EXPECT_FLOAT_EQ(b.lower.x, 10.0f);
    EXPECT_FLOAT_EQ(b.upper.x, 11.0f);
    const Material& m = l.scene.materials.at(l.scene.triangles[0].material);
    EXPECT_FLOAT_EQ(m.diffuse.x, 0.2f);
    EXPECT_FLOAT_EQ(m.diffuse.y, 0.4f);
    EXPECT_FLOAT_EQ(m.diffuse.z, 0.6f);
}

TEST(MeshLoader, EmissionFromMtlKeAndGltfEmissiveTimesItsStrength) {
    TempDir dir;
    dir.write("m.mtl", "newmtl lamp\nKd 0.5 0.5 0.5\nKe 17 12 4\nnewmtl odd\nKe -1 nan 2\n"
                       "newmtl plain\nKd 0.7 0.7 0.7\n");
    const Loaded obj = load(dir.write(
        "t.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl lamp\nf 1 2 3\n"
                 "usemtl odd\nf 1 2 4\nusemtl plain\nf 1 3 4\n"));
    ASSERT_TRUE(obj.ok) << obj.error;
    ASSERT_EQ(obj.scene.triangles.size(), 3u);
    const auto emission = [&](std::size_t t) {
        return obj.scene.materials.at(obj.scene.triangles[t].material).emission;
    };
    EXPECT_EQ(emission(0), glm::vec3(17.0f, 12.0f, 4.0f)); // Le, not clamped to 1
    EXPECT_EQ(emission(1), glm::vec3(0.0f, 0.0f, 2.0f));   // negative and NaN are no light
    EXPECT_EQ(emission(2), glm::vec3(0.0f));

    // glTF: emissiveFactor times KHR_materials_emissive_strength.
    const std::string gltf =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
        R"("extensionsUsed":["KHR_materials_emissive_strength"],)"
        R"("nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],)"
        R"("materials":[{"emissiveFactor":[0.5,0.25,1],)"
        R"("extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":4}}}],)"
        R"("buffers":[{"byteLength":44,"uri":"data:application/octet-stream;base64,)"
        R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],)"
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)"
        R"({"buffer":0,"byteOffset":36,"byteLength":6}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5123,"count":3,)"
        R"("type":"SCALAR"}]})";
    const Loaded l = load(dir.write("lamp.gltf", gltf));
    ASSERT_TRUE(l.ok) << l.error;
    ASSERT_EQ(l.scene.triangles.size(), 1u);
    EXPECT_EQ(l.scene.materials.at(l.scene.triangles[0].material).emission,
              glm::vec3(2.0f, 1.0f, 4.0f));
}

TEST(MeshLoader, ObjWithoutMaterialsIsGrey) {
    TempDir dir;
    const Loaded l = load(dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    ASSERT_TRUE(l.ok) << l.error;
    ASSERT_EQ(l.scene.triangles.size(), 1u);
    EXPECT_EQ(l.scene.materials.at(l.scene.triangles[0].material).diffuse, glm::vec3(0.75f));
    EXPECT_EQ(describe(l.report, "t.obj"), "");
}

TEST(MeshLoader, KdIsClampedToUnitRange) {
    TempDir dir;
    dir.write("m.mtl", "newmtl hot\nKd 2.5 -1 0.5\n");
    const Loaded l =
        load(dir.write("t.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl hot\nf 1 2 3\n"));
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_EQ(l.scene.materials.at(l.scene.triangles[0].material).diffuse,
              glm::vec3(1.0f, 0.0f, 0.5f));
}

TEST(MeshLoader, MissingMtlWarnsAndUsesGrey) {
    TempDir dir;
    const std::string path =
        dir.write("t.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    const Loaded l = load(path);
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_TRUE(l.report.missingMaterialLibrary);
    EXPECT_EQ(l.scene.materials.at(l.scene.triangles[0].material).diffuse, glm::vec3(0.75f));
    const std::string warning = describe(l.report, path);
    EXPECT_NE(warning.find(path), std::string::npos);
    EXPECT_NE(warning.find("material library"), std::string::npos);
}

TEST(MeshLoader, NonFiniteVerticesAreSkippedAndCounted) {
    TempDir dir;
    const std::string path = dir.write("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\n"
                                                  "v 0 inf 0\nf 1 2 3\nf 1 2 4\nf 1 5 3\n");
    const Loaded l = load(path);
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_EQ(l.scene.triangles.size(), 1u);
    EXPECT_EQ(l.report.nonFiniteTriangles, 2u);
    EXPECT_EQ(describe(l.report, path), path + ": skipped 2 non-finite triangles\n");
}

TEST(MeshLoader, BinaryPlyNanIsNonFiniteNotMerged) {
    TempDir dir;
    std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                      "property float y\nproperty float z\nelement face 2\n"
                      "property list uchar int vertex_indices\nend_header\n";
    const float v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0};
    ply.append(reinterpret_cast<const char*>(v), sizeof v);
    for (const int32_t last : {2, 3}) {
        const int32_t face[3] = {0, 1, last};
        ply.push_back('\3');
        ply.append(reinterpret_cast<const char*>(face), sizeof face);
    }
    const Loaded l = load(dir.write("nan.ply", ply));
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_EQ(l.scene.triangles.size(), 1u);
    EXPECT_EQ(l.report.nonFiniteTriangles, 1u);
    EXPECT_EQ(l.report.degenerateTriangles, 0u);
}

TEST(MeshLoader, DegenerateTrianglesAreSkippedAndCounted) {
    TempDir dir;
    const std::string path =
        dir.write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 1 1 1\n");
    const Loaded l = load(path);
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_EQ(l.scene.triangles.size(), 1u);
    EXPECT_EQ(l.report.degenerateTriangles, 2u);
    EXPECT_EQ(describe(l.report, path), path + ": skipped 2 degenerate triangles\n");
}

TEST(MeshLoader, PointsAndLinesAreSkippedAndCounted) {
    TempDir dir;
    const Loaded l = load(dir.write("pl.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1\nl 1 2\nf 1 2 3\n"));
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_EQ(l.scene.triangles.size(), 1u);
    EXPECT_EQ(l.report.nonTriangleFaces, 2u);
}

TEST(MeshLoader, QuadsAndPolygonsAreTriangulated) {
    TempDir dir;
    const Loaded l = load(dir.write(
        "q.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0.5 0\nf 1 2 3 4\nf 1 2 3 4 5\n"));
    ASSERT_TRUE(l.ok) << l.error;
    EXPECT_EQ(l.scene.triangles.size(), 2u + 3u);
}

// ---- generated files that fail ---------------------------------------------------------------

TEST(MeshLoaderErrors, MissingFile) {
    const std::string path = "/nonexistent/raylab/mesh.obj";
    const Loaded l = load(path);
    expectCleanFailure(l, path);
    EXPECT_NE(l.error.find("No such file"), std::string::npos) << l.error;
}

TEST(MeshLoaderErrors, Directory) {
    TempDir dir;
    const std::string path = dir.write("x", "");
    fs::remove(path);
    fs::create_directory(path);
    expectCleanFailure(load(path), path);
}

TEST(MeshLoaderErrors, EmptyFiles) {
    TempDir dir;
    for (const char* name : {"e.obj", "e.ply", "e.gltf", "e.stl"}) {
        const std::string path = dir.write(name, "");
        const Loaded l = load(path);
        expectCleanFailure(l, path);
        EXPECT_NE(l.error.find("empty"), std::string::npos) << l.error;
    }
}

TEST(MeshLoaderErrors, TruncatedPly) {
    TempDir dir;
    // Vertices cut short, then a face cut short: Assimp's own assertions fire on these (they
    // would abort the process without the handler in assimp_assert.cpp).
    for (const std::string& body :
         {std::string("0 0 0\n1 0 0\n"), std::string("0 0 0\n1 0 0\n0 1 0\n3 0 1\n")}) {
        const std::string path = dir.write("t.ply", kPlyHeader3 + body);
        expectCleanFailure(load(path), path);
    }
}

TEST(MeshLoaderErrors, TruncatedRealPly) {
    const fs::path p = test::asset("bunny/bun_zipper_res2.ply");
    if (p.empty()) {
        GTEST_SKIP() << "shared assets not found";
    }
    TempDir dir;
    std::ifstream in(p, std::ios::binary);
    std::string bytes(3000, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    const std::string path = dir.write("cut.ply", bytes);
    expectCleanFailure(load(path), path);
}

TEST(MeshLoaderErrors, PlyHeadersAssimpMishandles) {
    TempDir dir;
    // A forged element count: Assimp would try to allocate for four billion vertices.
    std::string forged = kPlyHeader3;
    forged.replace(forged.find("vertex 3"), 8, "vertex 4000000000");
    const std::string huge = dir.write("huge.ply", forged + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    Loaded l = load(huge);
    expectCleanFailure(l, huge);
    EXPECT_NE(l.error.find("more elements than the file has bytes"), std::string::npos) << l.error;
    // The same under another extension: Assimp picks its PLY reader by content too.
    const std::string disguised = dir.write("huge.mesh", forged + "0 0 0\n");
    expectCleanFailure(load(disguised), disguised);
    // No end_header line: Assimp 5.2 would read forever.
    const std::string endless =
        dir.write("endless.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                 "end_headeeader\nr\n");
    l = load(endless);
    expectCleanFailure(l, endless);
    EXPECT_NE(l.error.find("end_header"), std::string::npos) << l.error;
}

TEST(MeshLoaderErrors, RandomBytesUnderEveryExtension) {
    TempDir dir;
    std::mt19937 rng(12345);
    std::string bytes(4096, '\0');
    for (char& c : bytes) {
        c = static_cast<char>(rng() & 0xff);
    }
    for (const char* ext : {".obj", ".ply", ".gltf", ".glb", ".stl", ".fbx", ".off", ".xyz"}) {
        const std::string path = dir.write(std::string("garbage") + ext, bytes);
        expectCleanFailure(load(path), path);
    }
}

TEST(MeshLoaderErrors, IndicesOutOfRange) {
    TempDir dir;
    const std::string obj = dir.write("oor.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    expectCleanFailure(load(obj), obj);
    const std::string neg = dir.write("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n");
    expectCleanFailure(load(neg), neg);
    const std::string ply = dir.write("oor.ply", kPlyHeader3 + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    const Loaded l = load(ply);
    expectCleanFailure(l, ply);
    EXPECT_NE(l.error.find("out of range"), std::string::npos) << l.error;
}

TEST(MeshLoaderErrors, NoValidTriangleSaysWhatWasSkipped) {
    TempDir dir;
    const std::string path = dir.write("deg.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    const Loaded l = load(path);
    expectCleanFailure(l, path);
    EXPECT_NE(l.error.find("no valid triangle"), std::string::npos) << l.error;
    EXPECT_NE(l.error.find("1 degenerate triangle"), std::string::npos) << l.error;
    const std::string lines = dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
    expectCleanFailure(load(lines), lines);
    const std::string noFaces = dir.write("nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    expectCleanFailure(load(noFaces), noFaces);
}

TEST(MeshLoaderErrors, FailureLeavesTheSceneUntouched) {
    TempDir dir;
    Scene scene = makeCornellBox();
    MeshLoadReport report;
    std::string error;
    EXPECT_FALSE(loadMesh(dir.write("bad.ply", "not a ply"), scene, report, error));
    EXPECT_EQ(scene.triangles.size(), 30u);
}

} // namespace
} // namespace raylab
