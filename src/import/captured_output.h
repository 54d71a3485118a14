#pragma once
// What the reader prints itself: some Assimp importers write to standard output or error (a
// broken OpenGEX file prints "nullptr returned by creating DDLNode."). In raylab-import both
// descriptors go into a pipe of its own, which is read back after the load and sent to the
// parent as warning lines, sanitised and capped, never to the user's terminal as they are.

#include <string>
#include <vector>

namespace raylab::import {

class CapturedOutput {
public:
    // Makes descriptors 1 and 2 the write end of a non-blocking pipe (a reader that prints more
    // than the pipe holds, 64 KiB, loses the rest; it never blocks). Call before the sandbox.
    bool begin(std::string& error);
    // The lines printed since begin, without empty ones: at most kMaxLines of at most
    // kImportMaxText bytes each.
    std::vector<std::string> lines();

    static constexpr std::size_t kMaxLines = 16;

private:
    int readEnd_ = -1;
};

} // namespace raylab::import
