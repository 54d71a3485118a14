#pragma once
// The byte stream raylab-import sends its parent over a pipe: a versioned, little-endian record
// of one import's outcome. The helper writes it with writeImportScene (or encodeImport*); the
// parent reads it with parseImportStream, which trusts nothing: every count is checked against
// the bytes that are there, every index and value against its range, and the whole against a
// hard size cap.
//
// Layout (all integers little-endian, floats IEEE-754 binary32):
//   magic "RLIMPORT", u32 version (kImportStreamVersion), u64 total bytes of the stream (so the
//   parent can take the room at once), u8 kind
//   kind 0 (scene):
//     report: u64 nonFinite, u64 degenerate, u64 badIndex, u64 nonTriangle, u8 missingMtl
//     u32 warnings, each: u32 length, bytes
//     u32 materials (>= 1), each: u32 name length, bytes, f32 diffuse[3], f32 emission[3]
//     u64 triangles (>= 1), each: f32 v0[3], v1[3], v2[3], u32 material
//   kind 1 (error): u32 length, bytes (one line; the file's name is added by the parent)
//   then the end mark "DONE"; nothing may follow it.

#include "core/scene.h"
#include "io/mesh_loader.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace raylab {

inline constexpr uint32_t kImportStreamVersion = 1;

// raylab-import's exit codes, the other half of what it tells its parent.
inline constexpr int kImportExitDone = 0;        // the stream was sent (a scene or an error)
inline constexpr int kImportExitUsage = 2;       // bad arguments or no sandbox; an error was sent
inline constexpr int kImportExitOutOfMemory = 3; // operator new failed under the memory limit
inline constexpr int kImportExitAssertion = 4;   // Assimp's internal check failed; its text sent
inline constexpr int kImportExitPipeClosed = 5;  // the parent stopped reading
inline constexpr std::size_t kImportTriangleBytes = 40;
// Hard caps: nothing larger is read. 64 Mi triangles (2.5 GiB of stream) is far beyond any mesh
// the viewer could trace interactively.
inline constexpr std::size_t kImportMaxTriangles = std::size_t{64} << 20;
inline constexpr std::size_t kImportMaxMaterials = std::size_t{1} << 16;
inline constexpr std::size_t kImportMaxStreamBytes =
    kImportMaxTriangles * kImportTriangleBytes + (std::size_t{64} << 20);
inline constexpr std::size_t kImportMaxText = 4096; // one warning, error or material name
inline constexpr std::size_t kImportMaxWarnings = 256;

// What an import gives the parent: a scene with its report and warnings, or one error line.
struct ImportOutcome {
    bool ok = false;
    Scene scene;                       // valid when ok
    MeshLoadReport report;             // valid when ok
    std::vector<std::string> warnings; // extra lines from the importer; may be empty
    std::string error;                 // the helper's reason, one line, when !ok
};

// Takes the next piece of a stream being written; false stops the writing (the pipe is gone).
using ImportSink = std::function<bool(const uint8_t* bytes, std::size_t size)>;

// The helper's side. writeImportScene hands the stream to `sink` in pieces of at most 1 MiB,
// without holding it whole; false when the sink failed. At most kImportMaxWarnings warnings are
// kept. The encode* functions return the whole stream, end mark included.
bool writeImportScene(const Scene& scene, const MeshLoadReport& report,
                      const std::vector<std::string>& warnings, const ImportSink& sink);
std::vector<uint8_t> encodeImportScene(const Scene& scene, const MeshLoadReport& report,
                                       const std::vector<std::string>& warnings);
std::vector<uint8_t> encodeImportError(const std::string& error);

// The total a stream's header declares, once `size` bytes of it have arrived; 0 while the header
// is incomplete or not an import stream's. A hint for the reader's buffer: parseImportStream
// checks it against the bytes.
std::size_t declaredImportStreamBytes(const uint8_t* bytes, std::size_t size);

// The parent's side. Returns true with `out` filled when `bytes` is a well-formed stream whose
// scene has at least one triangle, every triangle valid (finite, non-zero area) with a material
// in range, diffuse colours in [0, 1] and emissions finite and >= 0. An error stream is
// well-formed too: true with out.ok false and out.error its (sanitised) line. Returns false with
// one line in `problem` otherwise.
bool parseImportStream(const uint8_t* bytes, std::size_t size, ImportOutcome& out,
                       std::string& problem);

// `text` made one printable line of at most kImportMaxText bytes (control bytes become spaces).
std::string sanitisedLine(const std::string& text);

} // namespace raylab
