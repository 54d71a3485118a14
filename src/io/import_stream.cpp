// The import stream (import_stream.h): writing it in the helper, reading and validating it in
// the parent.

#include "io/import_stream.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace raylab {

namespace {

constexpr char kMagic[8] = {'R', 'L', 'I', 'M', 'P', 'O', 'R', 'T'};
constexpr char kEnd[4] = {'D', 'O', 'N', 'E'};
constexpr uint8_t kKindScene = 0;
constexpr uint8_t kKindError = 1;

static_assert(std::endian::native == std::endian::little,
              "the import stream is written and read as the machine's little-endian bytes");

class Writer {
public:
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const uint8_t*>(data);
        out_.insert(out_.end(), p, p + n);
    }
    void u8(uint8_t v) { out_.push_back(v); }
    void u32(uint32_t v) { bytes(&v, sizeof v); }
    void u64(uint64_t v) { bytes(&v, sizeof v); }
    void f32(float v) { bytes(&v, sizeof v); }
    void vec3(const glm::vec3& v) {
        f32(v.x);
        f32(v.y);
        f32(v.z);
    }
    void text(const std::string& s) {
        const std::string line = sanitisedLine(s);
        u32(static_cast<uint32_t>(line.size()));
        bytes(line.data(), line.size());
    }
    void reserve(std::size_t n) { out_.reserve(n); }
    std::vector<uint8_t> take() { return std::move(out_); }

private:
    std::vector<uint8_t> out_;
};

void writeHeader(Writer& w, uint8_t kind) {
    w.bytes(kMagic, sizeof kMagic);
    w.u32(kImportStreamVersion);
    w.u8(kind);
}

// Reads fixed-size values off the front of a byte range; every read checks the bytes remain.
class Reader {
public:
    Reader(const uint8_t* p, std::size_t n) : p_(p), left_(n) {}
    std::size_t left() const { return left_; }
    bool bytes(void* out, std::size_t n) {
        if (n > left_) {
            return false;
        }
        std::memcpy(out, p_, n);
        p_ += n;
        left_ -= n;
        return true;
    }
    bool u8(uint8_t& v) { return bytes(&v, sizeof v); }
    bool u32(uint32_t& v) { return bytes(&v, sizeof v); }
    bool u64(uint64_t& v) { return bytes(&v, sizeof v); }
    bool vec3(glm::vec3& v) {
        float f[3];
        if (!bytes(f, sizeof f)) {
            return false;
        }
        v = glm::vec3(f[0], f[1], f[2]);
        return true;
    }
    bool text(std::string& s) {
        uint32_t n = 0;
        if (!u32(n) || n > kImportMaxText || n > left_) {
            return false;
        }
        s.assign(reinterpret_cast<const char*>(p_), n);
        p_ += n;
        left_ -= n;
        return true;
    }

private:
    const uint8_t* p_;
    std::size_t left_;
};

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool inUnitRange(const glm::vec3& v) {
    return v.x >= 0.0f && v.x <= 1.0f && v.y >= 0.0f && v.y <= 1.0f && v.z >= 0.0f && v.z <= 1.0f;
}

bool readReport(Reader& r, MeshLoadReport& report) {
    uint64_t counts[4] = {};
    uint8_t missing = 0;
    if (!r.u64(counts[0]) || !r.u64(counts[1]) || !r.u64(counts[2]) || !r.u64(counts[3]) ||
        !r.u8(missing) || missing > 1) {
        return false;
    }
    report.nonFiniteTriangles = counts[0];
    report.degenerateTriangles = counts[1];
    report.badIndexFaces = counts[2];
    report.nonTriangleFaces = counts[3];
    report.missingMaterialLibrary = missing == 1;
    return true;
}

// The scene part after the header; `problem` says what was wrong.
bool readScene(Reader& r, ImportOutcome& out, std::string& problem) {
    if (!readReport(r, out.report)) {
        problem = "a malformed load report";
        return false;
    }
    uint32_t warnings = 0;
    if (!r.u32(warnings) || warnings > kImportMaxWarnings) {
        problem = "a malformed warning count";
        return false;
    }
    for (uint32_t i = 0; i < warnings; ++i) {
        std::string line;
        if (!r.text(line)) {
            problem = "a truncated or oversized warning";
            return false;
        }
        out.warnings.push_back(sanitisedLine(line));
    }
    uint32_t materials = 0;
    // Each material takes at least 28 bytes.
    if (!r.u32(materials) || materials == 0 || materials > kImportMaxMaterials ||
        std::size_t{materials} * 28 > r.left()) {
        problem = "a material count that does not match the data";
        return false;
    }
    out.scene.materials.resize(materials);
    for (Material& m : out.scene.materials) {
        if (!r.text(m.name) || !r.vec3(m.diffuse) || !r.vec3(m.emission)) {
            problem = "a truncated material";
            return false;
        }
        m.name = sanitisedLine(m.name);
        if (!inUnitRange(m.diffuse) || !finite(m.emission) || m.emission.x < 0.0f ||
            m.emission.y < 0.0f || m.emission.z < 0.0f) {
            problem = "a material colour out of range";
            return false;
        }
    }
    uint64_t triangles = 0;
    if (!r.u64(triangles) || triangles == 0 || triangles > kImportMaxTriangles ||
        triangles * kImportTriangleBytes + sizeof kEnd != r.left()) {
        problem = "a triangle count that does not match the data";
        return false;
    }
    out.scene.triangles.resize(triangles);
    for (Triangle& t : out.scene.triangles) {
        r.vec3(t.v0); // the sizes were checked above
        r.vec3(t.v1);
        r.vec3(t.v2);
        r.u32(t.material);
        if (t.material >= materials) {
            problem = "a material index out of range";
            return false;
        }
        if (!isValidTriangle(t)) {
            problem = "a non-finite or degenerate triangle";
            return false;
        }
    }
    return true;
}

} // namespace

std::string sanitisedLine(const std::string& text) {
    std::string line = text.substr(0, kImportMaxText);
    for (char& c : line) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
            c = ' ';
        }
    }
    return line;
}

std::vector<uint8_t> encodeImportScene(const Scene& scene, const MeshLoadReport& report,
                                       const std::vector<std::string>& warnings) {
    Writer w;
    w.reserve(256 + scene.materials.size() * 64 + scene.triangles.size() * kImportTriangleBytes);
    writeHeader(w, kKindScene);
    w.u64(report.nonFiniteTriangles);
    w.u64(report.degenerateTriangles);
    w.u64(report.badIndexFaces);
    w.u64(report.nonTriangleFaces);
    w.u8(report.missingMaterialLibrary ? 1 : 0);
    const std::size_t kept = std::min(warnings.size(), kImportMaxWarnings);
    w.u32(static_cast<uint32_t>(kept));
    for (std::size_t i = 0; i < kept; ++i) {
        w.text(warnings[i]);
    }
    w.u32(static_cast<uint32_t>(scene.materials.size()));
    for (const Material& m : scene.materials) {
        w.text(m.name);
        w.vec3(m.diffuse);
        w.vec3(m.emission);
    }
    w.u64(scene.triangles.size());
    for (const Triangle& t : scene.triangles) {
        w.vec3(t.v0);
        w.vec3(t.v1);
        w.vec3(t.v2);
        w.u32(t.material);
    }
    w.bytes(kEnd, sizeof kEnd);
    return w.take();
}

std::vector<uint8_t> encodeImportError(const std::string& error) {
    Writer w;
    writeHeader(w, kKindError);
    w.text(error);
    w.bytes(kEnd, sizeof kEnd);
    return w.take();
}

bool parseImportStream(const uint8_t* bytes, std::size_t size, ImportOutcome& out,
                       std::string& problem) {
    out = ImportOutcome{};
    if (size > kImportMaxStreamBytes) {
        problem = "the importer sent more than the size cap";
        return false;
    }
    Reader r(bytes, size);
    char magic[sizeof kMagic] = {};
    uint32_t version = 0;
    uint8_t kind = 0;
    if (!r.bytes(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
        problem = "the importer's answer is not an import stream";
        return false;
    }
    if (!r.u32(version) || version != kImportStreamVersion) {
        problem = "the importer speaks another stream version";
        return false;
    }
    if (!r.u8(kind) || (kind != kKindScene && kind != kKindError)) {
        problem = "the importer's answer has an unknown kind";
        return false;
    }
    if (kind == kKindError) {
        if (!r.text(out.error)) {
            problem = "the importer's error is truncated";
            return false;
        }
        out.error = sanitisedLine(out.error);
        if (out.error.empty()) {
            out.error = "unknown error";
        }
    } else if (!readScene(r, out, problem)) {
        problem = "the importer's answer has " + problem;
        out = ImportOutcome{};
        return false;
    }
    char end[sizeof kEnd] = {};
    if (!r.bytes(end, sizeof end) || std::memcmp(end, kEnd, sizeof kEnd) != 0 || r.left() != 0) {
        problem = "the importer's answer does not end where it should";
        out = ImportOutcome{};
        return false;
    }
    out.ok = kind == kKindScene;
    return true;
}

} // namespace raylab
