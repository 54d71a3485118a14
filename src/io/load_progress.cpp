#include "io/load_progress.h"

#include <cstdio>
#include <unistd.h>
#include <utility>

namespace raylab {

LoadProgressLine::LoadProgressLine(std::string program, std::string path)
    : program_(std::move(program)), path_(std::move(path)), enabled_(::isatty(STDERR_FILENO) == 1) {
}

LoadProgressLine::~LoadProgressLine() {
    if (shownSecond_ >= 0) {
        std::fputs("\r\033[K", stderr); // back to the line's start, erase it
        std::fflush(stderr);
    }
}

ImportControl LoadProgressLine::control() {
    ImportControl c;
    c.running = [this](double seconds) { show(seconds); };
    return c;
}

void LoadProgressLine::show(double seconds) {
    const int second = static_cast<int>(seconds);
    if (!enabled_ || second < 2 || second == shownSecond_) {
        return;
    }
    std::fprintf(stderr, "\r%s: loading %s (%d s)", program_.c_str(), path_.c_str(), second);
    std::fflush(stderr);
    shownSecond_ = second;
}

} // namespace raylab
