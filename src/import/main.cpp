// raylab-import: reads one mesh file for raylab's programs, confined (see sandbox.h), and sends
// the result on descriptor 3 as an import stream (io/import_stream.h). Not meant to be run by
// hand: io/mesh_import.h starts it as
//   raylab-import --memory-limit-bytes N -- FILE

#include "import_helper.h"
#include "io/import_stream.h"
#include "pipe_output.h"

#include <csignal>
#include <cstdlib>
#include <string>
#include <sys/prctl.h>
#include <unistd.h>

int main(int argc, char** argv) {
    // Ends with the parent (the pipe then has no reader), even if the parent is killed.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() == 1) {
        return raylab::kImportExitPipeClosed;
    }
    char* end = nullptr;
    if (argc != 5 || std::string(argv[1]) != "--memory-limit-bytes" ||
        std::string(argv[3]) != "--") {
        raylab::import::sendToParent(raylab::encodeImportError(
            "usage: raylab-import --memory-limit-bytes N -- FILE (started by raylab's programs)"));
        return raylab::kImportExitUsage;
    }
    const unsigned long long memory = std::strtoull(argv[2], &end, 10);
    if (end == argv[2] || *end != '\0' || memory == 0) {
        raylab::import::sendToParent(raylab::encodeImportError("bad memory limit"));
        return raylab::kImportExitUsage;
    }
    return raylab::import::runImport(argv[4], memory);
}
