// importMesh: raylab-import's run turned into a scene or one line that names the file.

#include "io/mesh_import.h"

#include "core/cornell_box.h"
#include "io/helper_path.h"
#include "io/helper_process.h"
#include "io/import_stream.h"

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>

namespace raylab {

namespace {

// The helper's allocator (glibc's tunables, read when the helper starts): transparent huge pages
// for its heap, and neither mmap for blocks under 256 MiB nor giving memory back, in steps of
// 64 MiB. Assimp's readers make many allocations, some of a megabyte and more, freed and made
// again; in a process that lives for one file and ends without freeing, these settings cut the
// page faults that otherwise take a large share of a load (PERFORMANCE.md, "Importing meshes").
// The memory limit still holds: it bounds the address space.
constexpr const char* kImportAllocatorTunables =
    "GLIBC_TUNABLES=glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=268435456:"
    "glibc.malloc.trim_threshold=268435456:glibc.malloc.top_pad=67108864";

// "4", "0.5": a limit as the user would have typed it.
std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string signalName(int sig) {
    const char* abbrev = ::sigabbrev_np(sig);
    return abbrev != nullptr ? std::string("SIG") + abbrev : "signal " + std::to_string(sig);
}

// What went wrong, when the run gave no scene; empty when the stream should be parsed.
std::string runProblem(const HelperRun& run, const ImportLimits& limits, double memoryGiB) {
    if (!run.started) {
        return run.error;
    }
    if (run.cancelled) {
        return "cancelled";
    }
    if (run.timedOut) {
        return "took longer than " + number(limits.seconds) + " s (the importer was stopped)";
    }
    if (run.overCap) {
        return "the importer sent more than " + std::to_string(kImportMaxStreamBytes >> 20) +
               " MiB";
    }
    if (run.signal == SIGSYS) {
        return "the importer was stopped by its sandbox (SIGSYS: a forbidden system call)";
    }
    if (run.signal != 0) {
        return "the importer crashed (" + signalName(run.signal) + ")";
    }
    if (run.exitCode == kImportExitOutOfMemory) {
        return "needed more than " + number(memoryGiB) +
               " GiB (the importer's memory limit; see --import-memory-limit)";
    }
    return {};
}

} // namespace

bool importMesh(const std::string& path, const ImportLimits& limits, Scene& scene,
                MeshLoadReport& report, std::vector<std::string>& warnings, std::string& error,
                const ImportControl& control) {
    const std::string prefix = "cannot load mesh '" + path + "': ";
    std::string why;
    const std::string helper = findImportHelper(why);
    if (helper.empty()) {
        error = prefix + why;
        return false;
    }
    const double memoryGiB = effectiveImportMemoryGiB(limits);
    const auto memoryBytes = static_cast<unsigned long long>(memoryGiB * 1073741824.0);
    HelperOptions options;
    options.seconds = limits.seconds;
    options.maxBytes = kImportMaxStreamBytes;
    options.expectedBytes = declaredImportStreamBytes;
    options.cancelled = control.cancelled;
    options.running = control.running;
    options.environment = {kImportAllocatorTunables};
    // The stream is checked while the helper ends; what it says counts only if the run went well.
    ImportOutcome outcome;
    bool parsed = false;
    std::string problem;
    options.received = [&](const std::vector<uint8_t>& data) {
        parsed = parseImportStream(data.data(), data.size(), outcome, problem);
    };
    const HelperRun run = runHelper(
        {helper, "--memory-limit-bytes", std::to_string(memoryBytes), "--", path}, options);
    if (const std::string runError = runProblem(run, limits, memoryGiB); !runError.empty()) {
        error = prefix + runError;
        return false;
    }
    if (run.data.empty() && run.exitCode != 0) {
        error = prefix + "the importer failed (exit code " + std::to_string(run.exitCode) + ")";
        return false;
    }
    if (!parsed) {
        error = prefix + problem +
                (run.exitCode != 0
                     ? " (the importer exited with code " + std::to_string(run.exitCode) + ")"
                     : "");
        return false;
    }
    if (!outcome.ok) {
        // The helper's own line names the file already when it comes from the reader.
        error = outcome.error.find("'" + path + "'") != std::string::npos ? outcome.error
                                                                          : prefix + outcome.error;
        return false;
    }
    if (run.exitCode != 0) {
        error = prefix + "the importer exited with code " + std::to_string(run.exitCode);
        return false;
    }
    scene = std::move(outcome.scene);
    scene.name = path;
    report = outcome.report;
    warnings = std::move(outcome.warnings);
    return true;
}

bool loadScene(const std::string& nameOrPath, const ImportLimits& limits, Scene& scene,
               std::string& warnings, std::string& error, const ImportControl& control) {
    if (isLabBoxName(nameOrPath)) {
        scene = makeCornellBox();
        warnings.clear();
        return true;
    }
    MeshLoadReport report;
    std::vector<std::string> lines;
    if (!importMesh(nameOrPath, limits, scene, report, lines, error, control)) {
        return false;
    }
    warnings = describe(report, nameOrPath);
    for (const std::string& line : lines) {
        warnings += nameOrPath + ": " + line + "\n";
    }
    return true;
}

} // namespace raylab
