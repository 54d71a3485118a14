#pragma once
// The helper's confinement, applied to itself before it reads the untrusted file: resource limits
// and a seccomp filter (libseccomp). After enterSandbox the process can read files (opened
// read-only), write to descriptors 1 to 3 (/dev/null twice and its pipe), manage its memory and
// exit. A network call, an exec, opening a file for writing, creating, renaming or removing one
// kills it with SIGSYS.

#include <cstdint>
#include <string>

namespace raylab::import {

// Address-space limit (RLIMIT_AS) in bytes, no core file, no file growth, few descriptors, and a
// CPU-time limit as a backstop to the parent's wall-clock kill. Builds with a sanitizer skip the
// address-space limit: their runtimes reserve terabytes of address space up front.
bool applyLimits(uint64_t memoryBytes, std::string& error);

// Loads the syscall filter. Returns false with `error` when the kernel refuses it.
bool enterSandbox(std::string& error);

} // namespace raylab::import
