#include "captured_output.h"

#include "io/import_stream.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <unistd.h>

namespace raylab::import {

bool CapturedOutput::begin(std::string& error) {
    int fds[2];
    if (::pipe2(fds, O_NONBLOCK | O_CLOEXEC) != 0 || ::dup2(fds[1], STDOUT_FILENO) < 0 ||
        ::dup2(fds[1], STDERR_FILENO) < 0) {
        error = std::string("cannot capture the importer's output: ") + std::strerror(errno);
        return false;
    }
    ::close(fds[1]);
    readEnd_ = fds[0];
    return true;
}

std::vector<std::string> CapturedOutput::lines() {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(stdout);
    std::fflush(stderr);
    std::string text;
    char chunk[4096];
    ssize_t n = 0;
    while (readEnd_ >= 0 && (n = ::read(readEnd_, chunk, sizeof chunk)) > 0) {
        text.append(chunk, static_cast<std::size_t>(n));
    }
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < text.size() && out.size() < kMaxLines) {
        std::size_t end = text.find('\n', start);
        end = end == std::string::npos ? text.size() : end;
        const std::string line = sanitisedLine(text.substr(start, end - start));
        if (line.find_first_not_of(' ') != std::string::npos) {
            out.push_back(line);
        }
        start = end + 1;
    }
    return out;
}

} // namespace raylab::import
