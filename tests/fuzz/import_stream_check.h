#pragma once
// One fuzz input for the parent's side of raylab-import's stream (io/import_stream.h): the bytes
// as they would arrive from a helper that is broken or taken over. parseImportStream must either
// refuse them with one line and nothing in its outcome, or give an outcome whose every value is
// in range (what the renderer and the BVH rely on), and that outcome must survive being written
// and read again unchanged. Shared by the libFuzzer target and the corpus replay test.

#include "core/scene.h"
#include "io/import_stream.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace raylab::fuzz {

inline bool printableLine(const std::string& s) {
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
            return false;
        }
    }
    return s.size() <= kImportMaxText;
}

// Returns an empty string when the parser behaved, otherwise what it did wrong.
inline std::string checkImportStream(const uint8_t* data, std::size_t size) {
    ImportOutcome out;
    std::string problem;
    if (!parseImportStream(data, size, out, problem)) {
        if (problem.empty() || !printableLine(problem)) {
            return "bad refusal line: '" + problem + "'";
        }
        if (out.ok || !out.scene.triangles.empty() || !out.scene.materials.empty() ||
            !out.warnings.empty() || !out.error.empty()) {
            return "a refused stream left an outcome behind";
        }
        return {};
    }
    if (!out.ok) {
        return out.error.empty() || !printableLine(out.error)
                   ? "bad error line: '" + out.error + "'"
                   : std::string();
    }
    if (out.scene.triangles.empty() || out.scene.materials.empty() ||
        out.warnings.size() > kImportMaxWarnings) {
        return "an accepted scene with no triangle, no material or too many warnings";
    }
    for (const std::string& w : out.warnings) {
        if (!printableLine(w)) {
            return "an unprintable warning";
        }
    }
    for (const Material& m : out.scene.materials) {
        const glm::vec3 d = m.diffuse;
        const glm::vec3 e = m.emission;
        if (!printableLine(m.name) || !(d.x >= 0.0f && d.x <= 1.0f) ||
            !(d.y >= 0.0f && d.y <= 1.0f) || !(d.z >= 0.0f && d.z <= 1.0f) || !std::isfinite(e.x) ||
            !std::isfinite(e.y) || !std::isfinite(e.z) || e.x < 0.0f || e.y < 0.0f || e.z < 0.0f) {
            return "an accepted material out of range";
        }
    }
    for (const Triangle& t : out.scene.triangles) {
        if (t.material >= out.scene.materials.size() || !isValidTriangle(t)) {
            return "an accepted triangle out of range";
        }
    }
    const std::vector<uint8_t> again = encodeImportScene(out.scene, out.report, out.warnings);
    ImportOutcome back;
    if (!parseImportStream(again.data(), again.size(), back, problem) ||
        back.scene.triangles.size() != out.scene.triangles.size() ||
        back.warnings != out.warnings) {
        return "an accepted scene does not survive being written again: " + problem;
    }
    return {};
}

} // namespace raylab::fuzz
