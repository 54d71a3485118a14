// The import stream (import_stream.h): writing it in the helper, reading and validating it in
// the parent.

#include "io/import_stream.h"

#include "core/huge_pages.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <type_traits>

namespace raylab {

namespace {

constexpr char kMagic[8] = {'R', 'L', 'I', 'M', 'P', 'O', 'R', 'T'};
constexpr char kEnd[4] = {'D', 'O', 'N', 'E'};
constexpr uint8_t kKindScene = 0;
constexpr uint8_t kKindError = 1;

static_assert(std::endian::native == std::endian::little,
              "the import stream is written and read as the machine's little-endian bytes");

constexpr std::size_t kHeaderBytes = sizeof kMagic + 4 + 8 + 1;
constexpr std::size_t kReportBytes = 4 * 8 + 1;
constexpr std::size_t kSinkPiece = std::size_t{1} << 20;

// A Triangle's bytes are the stream's triangle record (nine floats, then the material), so the
// triangles are written and read as one block.
static_assert(sizeof(Triangle) == kImportTriangleBytes && offsetof(Triangle, v0) == 0 &&
                  offsetof(Triangle, v1) == 12 && offsetof(Triangle, v2) == 24 &&
                  offsetof(Triangle, material) == 36 && std::is_trivially_copyable_v<Triangle>,
              "Triangle must be laid out as the import stream's triangle record");

// Gathers what is written into pieces of kSinkPiece bytes for the sink; after the sink failed,
// writes nothing more.
class Writer {
public:
    explicit Writer(const ImportSink& sink) : sink_(sink) { buffer_.reserve(kSinkPiece); }
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const uint8_t*>(data);
        while (n > 0) {
            const std::size_t take = std::min(n, kSinkPiece - buffer_.size());
            buffer_.insert(buffer_.end(), p, p + take);
            p += take;
            n -= take;
            if (buffer_.size() == kSinkPiece) {
                flush();
            }
        }
    }
    void u8(uint8_t v) { bytes(&v, sizeof v); }
    void u32(uint32_t v) { bytes(&v, sizeof v); }
    void u64(uint64_t v) { bytes(&v, sizeof v); }
    void vec3(const glm::vec3& v) {
        const float f[3] = {v.x, v.y, v.z};
        bytes(f, sizeof f);
    }
    // Hands `n` bytes to the sink from where they are, after what is gathered, in pieces of at
    // most kSinkPiece bytes: the triangles go out without a copy.
    void direct(const void* data, std::size_t n) {
        flush();
        const auto* p = static_cast<const uint8_t*>(data);
        while (ok_ && n > 0) {
            const std::size_t take = std::min(n, kSinkPiece);
            ok_ = sink_(p, take);
            p += take;
            n -= take;
        }
    }
    void text(const std::string& s) {
        const std::string line = sanitisedLine(s);
        u32(static_cast<uint32_t>(line.size()));
        bytes(line.data(), line.size());
    }
    // Hands over what is left; false when the sink failed at any point.
    bool finish() {
        flush();
        return ok_;
    }

private:
    void flush() {
        if (ok_ && !buffer_.empty()) {
            ok_ = sink_(buffer_.data(), buffer_.size());
        }
        buffer_.clear();
    }
    const ImportSink& sink_;
    std::vector<uint8_t> buffer_;
    bool ok_ = true;
};

void writeHeader(Writer& w, uint64_t total, uint8_t kind) {
    w.bytes(kMagic, sizeof kMagic);
    w.u32(kImportStreamVersion);
    w.u64(total);
    w.u8(kind);
}

// The bytes Writer::text writes for `s`.
std::size_t textBytes(const std::string& s) { return 4 + std::min(s.size(), kImportMaxText); }

// The stream a vector sink collects.
std::vector<uint8_t> collect(const std::function<void(const ImportSink&)>& write) {
    std::vector<uint8_t> out;
    write([&out](const uint8_t* bytes, std::size_t size) {
        out.insert(out.end(), bytes, bytes + size);
        return true;
    });
    return out;
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
    // The next `n` bytes where they are, or null when fewer remain.
    const uint8_t* take(std::size_t n) {
        if (n > left_) {
            return nullptr;
        }
        const uint8_t* at = p_;
        p_ += n;
        left_ -= n;
        return at;
    }
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
    out.scene.triangles.reserve(triangles);
    adviseHugePages(out.scene.triangles.data(), triangles * sizeof(Triangle));
    out.scene.triangles.resize(triangles);
    const uint8_t* record = r.take(triangles * kImportTriangleBytes); // the size was checked above
    for (Triangle& t : out.scene.triangles) {
        std::memcpy(&t, record, kImportTriangleBytes);
        record += kImportTriangleBytes;
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

bool writeImportScene(const Scene& scene, const MeshLoadReport& report,
                      const std::vector<std::string>& warnings, const ImportSink& sink) {
    const std::size_t kept = std::min(warnings.size(), kImportMaxWarnings);
    std::size_t total = kHeaderBytes + kReportBytes + 4 + 4 + 8 +
                        scene.triangles.size() * kImportTriangleBytes + sizeof kEnd;
    for (std::size_t i = 0; i < kept; ++i) {
        total += textBytes(warnings[i]);
    }
    for (const Material& m : scene.materials) {
        total += textBytes(m.name) + 24;
    }
    Writer w(sink);
    writeHeader(w, total, kKindScene);
    w.u64(report.nonFiniteTriangles);
    w.u64(report.degenerateTriangles);
    w.u64(report.badIndexFaces);
    w.u64(report.nonTriangleFaces);
    w.u8(report.missingMaterialLibrary ? 1 : 0);
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
    w.direct(scene.triangles.data(), scene.triangles.size() * kImportTriangleBytes);
    w.bytes(kEnd, sizeof kEnd);
    return w.finish();
}

std::vector<uint8_t> encodeImportScene(const Scene& scene, const MeshLoadReport& report,
                                       const std::vector<std::string>& warnings) {
    return collect(
        [&](const ImportSink& sink) { writeImportScene(scene, report, warnings, sink); });
}

std::vector<uint8_t> encodeImportError(const std::string& error) {
    return collect([&](const ImportSink& sink) {
        Writer w(sink);
        writeHeader(w, kHeaderBytes + textBytes(error) + sizeof kEnd, kKindError);
        w.text(error);
        w.bytes(kEnd, sizeof kEnd);
        w.finish();
    });
}

std::size_t declaredImportStreamBytes(const uint8_t* bytes, std::size_t size) {
    if (size < kHeaderBytes || std::memcmp(bytes, kMagic, sizeof kMagic) != 0) {
        return 0;
    }
    uint64_t total = 0;
    std::memcpy(&total, bytes + sizeof kMagic + 4, sizeof total);
    return static_cast<std::size_t>(total);
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
    uint64_t total = 0;
    uint8_t kind = 0;
    if (!r.bytes(magic, sizeof magic) || std::memcmp(magic, kMagic, sizeof kMagic) != 0) {
        problem = "the importer's answer is not an import stream";
        return false;
    }
    if (!r.u32(version) || version != kImportStreamVersion) {
        problem = "the importer speaks another stream version";
        return false;
    }
    if (!r.u64(total) || total != size) {
        problem = "the importer's answer is not as long as it says";
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
