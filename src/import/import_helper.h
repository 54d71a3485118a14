#pragma once
// raylab-import's work, once its arguments are parsed: confine itself, read the file with the
// in-process loader (io/mesh_loader.h) and send the outcome to the parent on descriptor 3.

#include <cstdint>
#include <string>

namespace raylab::import {

// Returns the process's exit code (kImportExit*, io/import_stream.h) when confining itself
// failed; once the file has been read it ends the process itself (_exit, nothing freed).
int runImport(const std::string& path, uint64_t memoryBytes);

} // namespace raylab::import
