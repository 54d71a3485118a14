#pragma once
// raylab-import's work, once its arguments are parsed: confine itself, read the file with the
// in-process loader (io/mesh_loader.h) and send the outcome to the parent on descriptor 3.

#include <cstdint>
#include <string>

namespace raylab::import {

// The exit codes the parent reads (io/mesh_import.cpp).
inline constexpr int kExitDone = 0;        // the stream was sent (a scene or an error)
inline constexpr int kExitUsage = 2;       // bad arguments; an error stream was sent
inline constexpr int kExitOutOfMemory = 3; // operator new failed under the memory limit
inline constexpr int kExitAssertion = 4;   // Assimp's internal check failed; its text was sent
inline constexpr int kExitPipeClosed = 5;  // the parent stopped reading

int runImport(const std::string& path, uint64_t memoryBytes);

} // namespace raylab::import
