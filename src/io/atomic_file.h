#pragma once
// Writing a file so that it either appears whole or not at all: the content goes to a temporary
// file beside the target (same folder, so the final rename is atomic), which is renamed over the
// target only when everything was written and closed without error.

#include <cstdio>
#include <functional>
#include <string>

namespace raylab {

// Writes `path` through `writeBody`, which gets the open temporary file (binary mode) and returns
// false with `error` set on failure. On any failure the temporary file is removed and `error` is
// one line naming `path` and the reason (strerror for system errors). The new file gets mode 0644.
bool writeFileAtomically(const std::string& path,
                         const std::function<bool(std::FILE* file, std::string& error)>& writeBody,
                         std::string& error);

// Like writeFileAtomically for libraries that open files by name themselves (OpenEXR): `writeTo`
// gets the temporary file's path, which exists and is empty, and must write it completely.
bool writeFileAtomicallyByName(
    const std::string& path,
    const std::function<bool(const std::string& tempPath, std::string& error)>& writeTo,
    std::string& error);

// Checks, without leaving anything behind, that a file could be created at `path`: its folder
// exists and is writable (by creating and removing a temporary file there) and `path` is not a
// folder. Used before long renders so that a bad output path fails in a second, not after.
bool checkWritable(const std::string& path, std::string& error);

} // namespace raylab
