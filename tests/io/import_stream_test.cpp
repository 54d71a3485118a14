// The parent's reading of raylab-import's stream: a good stream round-trips, and every crafted
// corruption (truncation, counts that lie, NaN coordinates, indices and colours out of range,
// trailing bytes, another version) is refused with one line.

#include "import_stream_check.h"
#include "io/import_stream.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <limits>

namespace raylab {
namespace {

Scene twoTriangles() {
    Scene scene;
    Material red;
    red.name = "red";
    red.diffuse = glm::vec3(0.75f, 0.15f, 0.15f);
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = glm::vec3(17.0f, 12.0f, 4.0f);
    scene.materials = {red, lamp};
    Triangle a;
    a.v0 = glm::vec3(0.0f);
    a.v1 = glm::vec3(1.0f, 0.0f, 0.0f);
    a.v2 = glm::vec3(0.0f, 1.0f, 0.0f);
    Triangle b = a;
    b.v2 = glm::vec3(0.0f, 0.0f, 2.0f);
    b.material = 1;
    scene.triangles = {a, b};
    return scene;
}

// Offsets into the stream of twoTriangles() with the report below and no warnings.
constexpr std::size_t kHeader = 8 + 4 + 8 + 1;
constexpr std::size_t kTotal = 8 + 4; // the u64 total in the header
constexpr std::size_t kReport = 4 * 8 + 1;
constexpr std::size_t kMaterialCount = kHeader + kReport + 4;
constexpr std::size_t kFirstMaterial = kMaterialCount + 4;
constexpr std::size_t kMaterialBytes = 4 + 24; // plus the name
constexpr std::size_t kTriangleCount = kFirstMaterial + 2 * kMaterialBytes + 3 + 4;
constexpr std::size_t kFirstTriangle = kTriangleCount + 8;

std::vector<uint8_t> goodStream() {
    MeshLoadReport report;
    report.degenerateTriangles = 3;
    report.missingMaterialLibrary = true;
    return encodeImportScene(twoTriangles(), report, {});
}

// Parses and expects a refusal: false, one non-empty line, nothing in `out`.
void expectRefused(const std::vector<uint8_t>& bytes, const char* what) {
    ImportOutcome out;
    std::string problem;
    EXPECT_FALSE(parseImportStream(bytes.data(), bytes.size(), out, problem)) << what;
    EXPECT_FALSE(problem.empty()) << what;
    EXPECT_EQ(problem.find('\n'), std::string::npos) << what;
    EXPECT_TRUE(out.scene.triangles.empty()) << what;
    EXPECT_FALSE(out.ok) << what;
}

void putFloat(std::vector<uint8_t>& bytes, std::size_t at, float value) {
    std::memcpy(bytes.data() + at, &value, sizeof value);
}

void putU32(std::vector<uint8_t>& bytes, std::size_t at, uint32_t value) {
    std::memcpy(bytes.data() + at, &value, sizeof value);
}

TEST(ImportStream, SceneRoundTrips) {
    const std::vector<uint8_t> bytes =
        encodeImportScene(twoTriangles(), MeshLoadReport{}, {"a warning", "two\nlines"});
    ImportOutcome out;
    std::string problem;
    ASSERT_TRUE(parseImportStream(bytes.data(), bytes.size(), out, problem)) << problem;
    ASSERT_TRUE(out.ok);
    const Scene want = twoTriangles();
    ASSERT_EQ(out.scene.triangles.size(), 2u);
    EXPECT_EQ(out.scene.triangles[1].v2, want.triangles[1].v2);
    EXPECT_EQ(out.scene.triangles[1].material, 1u);
    ASSERT_EQ(out.scene.materials.size(), 2u);
    EXPECT_EQ(out.scene.materials[0].name, "red");
    EXPECT_EQ(out.scene.materials[0].diffuse, want.materials[0].diffuse);
    EXPECT_EQ(out.scene.materials[1].emission, glm::vec3(17.0f, 12.0f, 4.0f));
    ASSERT_EQ(out.warnings.size(), 2u);
    EXPECT_EQ(out.warnings[1], "two lines"); // one line each
}

TEST(ImportStream, ReportRoundTrips) {
    const std::vector<uint8_t> bytes = goodStream();
    ImportOutcome out;
    std::string problem;
    ASSERT_TRUE(parseImportStream(bytes.data(), bytes.size(), out, problem)) << problem;
    EXPECT_EQ(out.report.degenerateTriangles, 3u);
    EXPECT_EQ(out.report.nonFiniteTriangles, 0u);
    EXPECT_TRUE(out.report.missingMaterialLibrary);
}

TEST(ImportStream, ErrorRoundTripsAsOneLine) {
    const std::vector<uint8_t> bytes = encodeImportError("bad\nfile\r\x01");
    ImportOutcome out;
    std::string problem;
    ASSERT_TRUE(parseImportStream(bytes.data(), bytes.size(), out, problem)) << problem;
    EXPECT_FALSE(out.ok);
    EXPECT_EQ(out.error, "bad file  ");
}

TEST(ImportStream, EveryTruncationIsRefused) {
    const std::vector<uint8_t> bytes = goodStream();
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        expectRefused(std::vector<uint8_t>(bytes.begin(), bytes.begin() + n), "truncated");
    }
}

TEST(ImportStream, TrailingBytesAreRefused) {
    std::vector<uint8_t> bytes = goodStream();
    bytes.push_back(0);
    expectRefused(bytes, "trailing byte");
}

TEST(ImportStream, TheHeaderDeclaresTheTotalOnceItIsThere) {
    const std::vector<uint8_t> bytes = goodStream();
    EXPECT_EQ(declaredImportStreamBytes(bytes.data(), bytes.size()), bytes.size());
    EXPECT_EQ(declaredImportStreamBytes(bytes.data(), kHeader), bytes.size());
    EXPECT_EQ(declaredImportStreamBytes(bytes.data(), kHeader - 1), 0u);
    const std::vector<uint8_t> error = encodeImportError("no such file");
    EXPECT_EQ(declaredImportStreamBytes(error.data(), error.size()), error.size());
    std::vector<uint8_t> other = bytes;
    other[0] = 'X';
    EXPECT_EQ(declaredImportStreamBytes(other.data(), other.size()), 0u);
}

// A scene of more than 1 MiB reaches the sink in pieces of at most 1 MiB that make the same
// stream as encodeImportScene; a sink that fails stops the writing.
TEST(ImportStream, WritingGoesToTheSinkInPieces) {
    Scene big = twoTriangles();
    big.triangles.resize(60000, big.triangles[0]); // 2.4 MB of triangles
    std::vector<uint8_t> joined;
    std::size_t pieces = 0;
    ASSERT_TRUE(writeImportScene(big, MeshLoadReport{}, {}, [&](const uint8_t* p, std::size_t n) {
        EXPECT_LE(n, std::size_t{1} << 20);
        joined.insert(joined.end(), p, p + n);
        ++pieces;
        return true;
    }));
    // What comes before the triangles, their 2.4 MB straight from the scene in three, the end.
    EXPECT_EQ(pieces, 5u);
    EXPECT_EQ(joined, encodeImportScene(big, MeshLoadReport{}, {}));
    pieces = 0;
    EXPECT_FALSE(writeImportScene(big, MeshLoadReport{}, {}, [&](const uint8_t*, std::size_t) {
        ++pieces;
        return false;
    }));
    EXPECT_EQ(pieces, 1u);
}

TEST(ImportStream, TheOffsetsOfTheseTestsAreRight) {
    const std::vector<uint8_t> bytes = goodStream();
    uint32_t materials = 0;
    uint64_t triangles = 0;
    std::memcpy(&materials, bytes.data() + kMaterialCount, 4);
    std::memcpy(&triangles, bytes.data() + kTriangleCount, 8);
    EXPECT_EQ(materials, 2u);
    EXPECT_EQ(triangles, 2u);
    EXPECT_EQ(bytes.size(), kFirstTriangle + 2 * kImportTriangleBytes + 4);
}

TEST(ImportStream, LyingCountsAreRefused) {
    for (const uint64_t lie : {uint64_t{0}, uint64_t{1}, uint64_t{3}, uint64_t{1} << 40,
                               std::numeric_limits<uint64_t>::max()}) {
        std::vector<uint8_t> bytes = goodStream();
        std::memcpy(bytes.data() + kTriangleCount, &lie, sizeof lie);
        expectRefused(bytes, "triangle count");
    }
    for (const uint32_t lie : {0u, 1u, 3u, 0xffffffffu}) {
        std::vector<uint8_t> bytes = goodStream();
        putU32(bytes, kMaterialCount, lie);
        expectRefused(bytes, "material count");
    }
    std::vector<uint8_t> bytes = goodStream();
    putU32(bytes, kFirstMaterial, 0xfffffff0u); // the first name's length
    expectRefused(bytes, "name length");
    bytes = goodStream();
    putU32(bytes, kMaterialCount - 4, 5); // five warnings that are not there
    expectRefused(bytes, "warning count");
}

TEST(ImportStream, NonFiniteCoordinatesAreRefused) {
    for (const float bad :
         {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
          -std::numeric_limits<float>::infinity()}) {
        for (std::size_t coordinate = 0; coordinate < 9; ++coordinate) {
            std::vector<uint8_t> bytes = goodStream();
            putFloat(bytes, kFirstTriangle + kImportTriangleBytes + 4 * coordinate, bad);
            expectRefused(bytes, "non-finite coordinate");
        }
    }
}

TEST(ImportStream, DegenerateTrianglesAreRefused) {
    std::vector<uint8_t> bytes = goodStream();
    for (std::size_t i = 0; i < 9; ++i) {
        putFloat(bytes, kFirstTriangle + 4 * i, 1.0f); // three equal vertices
    }
    expectRefused(bytes, "degenerate triangle");
}

TEST(ImportStream, MaterialIndexOutOfRangeIsRefused) {
    for (const uint32_t index : {2u, 1000u, 0xffffffffu}) {
        std::vector<uint8_t> bytes = goodStream();
        putU32(bytes, kFirstTriangle + kImportTriangleBytes + 36, index);
        expectRefused(bytes, "material index");
    }
}

TEST(ImportStream, ColoursOutOfRangeAreRefused) {
    const std::size_t redDiffuse = kFirstMaterial + 4 + 3; // after the name "red"
    for (const float bad : {-0.1f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
        std::vector<uint8_t> bytes = goodStream();
        putFloat(bytes, redDiffuse, bad);
        expectRefused(bytes, "diffuse");
    }
    const std::size_t lampEmission = kFirstMaterial + kMaterialBytes + 3 + 4 + 4 + 12;
    for (const float bad :
         {-1.0f, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
        std::vector<uint8_t> bytes = goodStream();
        putFloat(bytes, lampEmission, bad);
        expectRefused(bytes, "emission");
    }
}

TEST(ImportStream, HeaderProblemsAreRefused) {
    std::vector<uint8_t> bytes = goodStream();
    bytes[0] = 'X';
    expectRefused(bytes, "magic");
    bytes = goodStream();
    putU32(bytes, 8, kImportStreamVersion + 1);
    expectRefused(bytes, "version");
    bytes = goodStream();
    bytes[kHeader - 1] = 7;
    expectRefused(bytes, "kind");
    for (const uint64_t lie : {uint64_t{0}, uint64_t{bytes.size() - 1}, uint64_t{bytes.size() + 1},
                               std::numeric_limits<uint64_t>::max()}) {
        bytes = goodStream();
        std::memcpy(bytes.data() + kTotal, &lie, sizeof lie);
        expectRefused(bytes, "declared total");
    }
    bytes = goodStream();
    bytes[bytes.size() - 1] = 'X';
    expectRefused(bytes, "end mark");
    bytes = goodStream();
    bytes[kHeader + 32] = 2; // missingMtl is 0 or 1
    expectRefused(bytes, "report flag");
}

// The fuzz target's seed corpus (tests/fuzz/corpus/import_stream), replayed in the normal build:
// every stream is refused in one line or accepted with every value in range, and the seeds hold
// both kinds.
TEST(ImportStream, TheFuzzCorpusIsReadAsTheFuzzTargetDemands) {
    std::size_t files = 0;
    std::size_t accepted = 0;
    for (const auto& entry : std::filesystem::directory_iterator(RAYLAB_IMPORT_STREAM_CORPUS_DIR)) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
        SCOPED_TRACE(entry.path().string());
        EXPECT_EQ(fuzz::checkImportStream(bytes.data(), bytes.size()), "");
        ImportOutcome out;
        std::string problem;
        accepted += parseImportStream(bytes.data(), bytes.size(), out, problem) && out.ok ? 1 : 0;
        ++files;
    }
    EXPECT_GE(files, 7u);
    EXPECT_GE(accepted, 2u);
    EXPECT_LT(accepted, files);
}

} // namespace
} // namespace raylab
