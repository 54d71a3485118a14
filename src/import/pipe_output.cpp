#include "pipe_output.h"

#include <cerrno>
#include <unistd.h>

namespace raylab::import {

bool sendToParent(const std::vector<uint8_t>& bytes) {
    return sendToParent(bytes.data(), bytes.size());
}

bool sendToParent(const uint8_t* bytes, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(kResultFd, bytes + done, size - done);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return true;
}

} // namespace raylab::import
