#include "import_helper.h"

#include "captured_output.h"
#include "io/assimp_assert.h"
#include "io/import_stream.h"
#include "io/mesh_loader.h"
#include "pipe_output.h"
#include "sandbox.h"
#include "test_hooks.h"

#include <new>
#include <unistd.h>

namespace raylab::import {

namespace {

// operator new failed: the memory limit was reached. Allocating anything more is hopeless, so
// the exit code alone tells the parent, which knows the limit it gave.
[[noreturn]] void outOfMemory() { ::_exit(kImportExitOutOfMemory); }

// Assimp's failed internal check: its text to the parent, then the end; nothing unwinds through
// Assimp.
[[noreturn]] void assertionFailed(const char* message) {
    sendToParent(encodeImportError(message));
    ::_exit(kImportExitAssertion);
}

// Closes the pipe first, so that the parent sees the end of the stream before the kernel takes
// this process's memory back.
[[noreturn]] void endImport(int code) {
    ::close(kResultFd);
    ::_exit(code);
}

int sendError(const std::string& error, int code) {
    return sendToParent(encodeImportError(error)) ? code : kImportExitPipeClosed;
}

} // namespace

int runImport(const std::string& path, uint64_t memoryBytes) {
    std::string error;
    CapturedOutput output;
    if (!output.begin(error) || !applyLimits(memoryBytes, error) || !enterSandbox(error)) {
        return sendError(error, kImportExitUsage);
    }
    std::set_new_handler(outOfMemory);
    setAssimpAssertionHandler(assertionFailed);
    runTestHook();

    // The reader and the scene are never destroyed: once the stream is sent, the pipe is closed
    // (the parent starts checking the stream) and _exit ends the process without freeing them.
    MeshReader reader;
    Scene scene;
    MeshLoadReport report;
    if (!reader.read(path, scene, report, error)) {
        endImport(sendError(error, kImportExitDone));
    }
    const bool sent =
        writeImportScene(scene, report, output.lines(), [](const uint8_t* bytes, std::size_t size) {
            return sendToParent(bytes, size);
        });
    endImport(sent ? kImportExitDone : kImportExitPipeClosed);
}

} // namespace raylab::import
