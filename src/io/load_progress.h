#pragma once
// What the command-line tools show on stderr while a mesh import runs long: after 2 s, and only
// when stderr is a terminal, "<program>: loading FILE (N s)" rewritten each second, erased at
// the end of the load (the object's destruction).

#include "io/mesh_import.h"

#include <string>

namespace raylab {

class LoadProgressLine {
public:
    LoadProgressLine(std::string program, std::string path);
    ~LoadProgressLine();
    LoadProgressLine(const LoadProgressLine&) = delete;
    LoadProgressLine& operator=(const LoadProgressLine&) = delete;

    // A control whose `running` updates this line; valid while this object lives.
    ImportControl control();

private:
    void show(double seconds);

    std::string program_;
    std::string path_;
    bool enabled_;
    int shownSecond_ = -1;
};

} // namespace raylab
