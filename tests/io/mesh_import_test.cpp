// importMesh through the real raylab-import: the same scene as the in-process reader, and each
// way a helper can fail (crash, sandbox kill, memory limit, time limit, cancel, garbage, missing)
// as one line that names the file, promptly.

#include "io/mesh_import.h"
#include "io/mesh_loader.h"
#include "io/sanitizer_build.h"
#include "temp_dir_test.h"
#include "test_assets.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

namespace raylab {
namespace {

using Clock = std::chrono::steady_clock;

// Sets an environment variable for one test's scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) { ::setenv(name, value, 1); }
    ~ScopedEnv() { ::unsetenv(name_); }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
};

struct Imported {
    bool ok = false;
    Scene scene;
    MeshLoadReport report;
    std::vector<std::string> warnings;
    std::string error;
    double seconds = 0.0;
};

Imported import(const std::string& path, const ImportLimits& limits = {},
                const ImportControl& control = {}) {
    Imported r;
    const auto start = Clock::now();
    r.ok = importMesh(path, limits, r.scene, r.report, r.warnings, r.error, control);
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return r;
}

// A failure: one line that names the file and contains `what`.
void expectFailure(const Imported& r, const std::string& path, const std::string& what) {
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("'" + path + "'"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find(what), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
    EXPECT_TRUE(r.scene.triangles.empty());
}

class MeshImport : public test::TempDirTest {
protected:
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(path(name), std::ios::binary) << text;
        return path(name);
    }
    std::string triangleObj() const {
        write("t.mtl", "newmtl lamp\nKd 0.5 0.25 1\nKe 4 2 0.5\n");
        return write("t.obj", "mtllib t.mtl\nusemtl lamp\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    }
};

TEST_F(MeshImport, ObjWithMaterialAndEmissionComesThrough) {
    const std::string obj = triangleObj();
    const Imported r = import(obj);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.scene.triangles.size(), 1u);
    EXPECT_EQ(r.scene.name, obj);
    EXPECT_EQ(r.scene.triangles[0].v1, glm::vec3(1.0f, 0.0f, 0.0f));
    const Material& m = r.scene.materials.at(r.scene.triangles[0].material);
    EXPECT_EQ(m.diffuse, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(m.emission, glm::vec3(4.0f, 2.0f, 0.5f));
}

TEST_F(MeshImport, SameSceneAsTheInProcessReader) {
    const auto bunny = test::asset("bunny/bun_zipper_res2.ply");
    if (bunny.empty()) {
        GTEST_SKIP() << "shared assets not found";
    }
    Scene direct;
    MeshLoadReport directReport;
    std::string error;
    ASSERT_TRUE(loadMesh(bunny.string(), direct, directReport, error)) << error;
    const Imported r = import(bunny.string());
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.scene.triangles.size(), direct.triangles.size());
    for (std::size_t i = 0; i < direct.triangles.size(); ++i) {
        ASSERT_EQ(r.scene.triangles[i].v0, direct.triangles[i].v0) << i;
        ASSERT_EQ(r.scene.triangles[i].v2, direct.triangles[i].v2) << i;
        ASSERT_EQ(r.scene.triangles[i].material, direct.triangles[i].material) << i;
    }
    EXPECT_EQ(r.report.degenerateTriangles, directReport.degenerateTriangles);
}

TEST_F(MeshImport, TheReadersOwnErrorNamesTheFile) {
    const Imported r = import(path("missing.obj"));
    expectFailure(r, path("missing.obj"), "No such file");
    const std::string junk = write("junk.obj", "this is not a mesh\n");
    expectFailure(import(junk), junk, "cannot load mesh");
}

// The 309-byte OFF file whose header claims 353,535,235,358 vertices.
TEST_F(MeshImport, ForgedOffHeaderFailsFastWithinTheMemoryLimit) {
    std::string off = "OFF\n353535235358 1 0\n";
    off += std::string(309 - off.size(), ' ');
    const std::string file = write("forged.off", off);
    ASSERT_EQ(std::filesystem::file_size(file), 309u);
    if (kSanitizerBuild) {
        GTEST_SKIP() << "a sanitizer build's helper has no address-space limit (sandbox.h): the "
                        "forged header would take about 15 GiB";
    }
    ImportLimits limits;
    limits.memoryGiB = 2.0;
    const Imported r = import(file, limits);
    expectFailure(r, file, "needed more than 2 GiB");
    EXPECT_LT(r.seconds, 10.0);
}

TEST_F(MeshImport, ACrashIsNamedBySignal) {
    const std::string obj = triangleObj();
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "segv");
    expectFailure(import(obj), obj, "the importer crashed (SIGSEGV)");
}

TEST_F(MeshImport, AnAbortIsNamedBySignal) {
    const std::string obj = triangleObj();
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "abort");
    expectFailure(import(obj), obj, "the importer crashed (SIGABRT)");
}

TEST_F(MeshImport, OpeningAFileForWritingKillsTheHelper) {
    const std::string obj = triangleObj();
    std::filesystem::remove("/tmp/raylab-import-escape");
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "write");
    expectFailure(import(obj), obj, "stopped by its sandbox (SIGSYS");
    EXPECT_FALSE(std::filesystem::exists("/tmp/raylab-import-escape"));
}

TEST_F(MeshImport, ASocketKillsTheHelper) {
    const std::string obj = triangleObj();
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "socket");
    expectFailure(import(obj), obj, "stopped by its sandbox (SIGSYS");
}

TEST_F(MeshImport, ExecKillsTheHelper) {
    const std::string obj = triangleObj();
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "exec");
    expectFailure(import(obj), obj, "stopped by its sandbox (SIGSYS");
}

TEST_F(MeshImport, AHangIsStoppedAtTheTimeLimit) {
    const std::string obj = triangleObj();
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "hang");
    ImportLimits limits;
    limits.seconds = 0.5;
    const Imported r = import(obj, limits);
    expectFailure(r, obj, "took longer than 0.5 s");
    EXPECT_GE(r.seconds, 0.5);
    EXPECT_LT(r.seconds, 5.0);
}

TEST_F(MeshImport, CancelStopsTheHelperAtOnce) {
    const std::string obj = triangleObj();
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "hang");
    std::atomic<int> polls{0};
    ImportControl control;
    control.running = [&](double) { ++polls; };
    control.cancelled = [&] { return polls.load() >= 5; };
    const Imported r = import(obj, ImportLimits{}, control);
    expectFailure(r, obj, "cancelled");
    EXPECT_LT(r.seconds, 3.0);
}

// What the reader prints itself comes back as the import's warnings, one printable line each.
TEST_F(MeshImport, TheReadersOwnOutputBecomesWarnings) {
    const std::string obj = triangleObj();
    ScopedEnv print("RAYLAB_IMPORT_TEST_CRASH", "print");
    const Imported r = import(obj);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.scene.triangles.size(), 1u);
    // Standard error is unbuffered, standard output flushed at the end: the order may differ.
    std::vector<std::string> lines = r.warnings;
    std::sort(lines.begin(), lines.end());
    EXPECT_EQ(lines, (std::vector<std::string>{"a second line [31m, on stderr",
                                               "nullptr returned by creating DDLNode."}));
}

TEST_F(MeshImport, AnExitWithoutAnAnswerIsNamedByItsCode) {
    const std::string obj = triangleObj();
    ScopedEnv exit("RAYLAB_IMPORT_TEST_CRASH", "exit");
    expectFailure(import(obj), obj, "the importer failed (exit code 66)");
}

TEST_F(MeshImport, GarbageFromTheHelperIsRefused) {
    const std::string obj = triangleObj();
    ScopedEnv crash("RAYLAB_IMPORT_TEST_CRASH", "garbage");
    expectFailure(import(obj), obj, "not an import stream");
}

TEST_F(MeshImport, AMissingHelperIsOneClearLine) {
    const std::string obj = triangleObj();
    ScopedEnv helper("RAYLAB_IMPORT_HELPER", "/nonexistent/raylab-import");
    expectFailure(import(obj), obj, "mesh importer '/nonexistent/raylab-import'");
}

TEST_F(MeshImport, LoadSceneGivesTheBoxWithoutTheHelper) {
    ScopedEnv helper("RAYLAB_IMPORT_HELPER", "/nonexistent/raylab-import");
    Scene scene;
    std::string warnings, error;
    ASSERT_TRUE(loadScene("cornell", ImportLimits{}, scene, warnings, error)) << error;
    EXPECT_EQ(scene.triangles.size(), 30u);
}

TEST(ImportLimits, NonsenseIsRefused) {
    double v = 7.0;
    for (const char* bad : {"0", "-1", "nan", "NaN", "inf", "", "1x", "2000", "-0"}) {
        EXPECT_FALSE(parseImportLimit(bad, kMaxImportMemoryGiB, v)) << bad;
    }
    EXPECT_EQ(v, 7.0);
    EXPECT_TRUE(parseImportLimit("0.5", kMaxImportMemoryGiB, v));
    EXPECT_EQ(v, 0.5);
    const double share = defaultImportMemoryGiB();
    EXPECT_GE(share, 1.0);
    EXPECT_LE(share, 4.0);
}

} // namespace
} // namespace raylab
