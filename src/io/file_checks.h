#pragma once
// Checks on a file named by a user before it is read whole: it must be a regular file (not a
// folder, a device such as /dev/zero, or a pipe that never ends) of at most maxBytes bytes.

#include <cstdint>
#include <string>

namespace raylab {

// Returns true with the file's size; else false with one line in `error`, "<what> '<path>': why".
bool checkRegularFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes,
                      std::uintmax_t& size, std::string& error);

// The whole of a regular file of at most maxBytes bytes (checkRegularFile's checks first). False
// with one line in `error`, "<what> '<path>'" and why.
bool readRegularTextFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes,
                         std::string& text, std::string& error);

} // namespace raylab
