#pragma once
// Writing the helper's answer to its parent: descriptor 3, the pipe runHelper gave it.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raylab::import {

inline constexpr int kResultFd = 3;

// Writes all of `bytes` to kResultFd; false when the pipe is gone (the parent stopped reading).
bool sendToParent(const uint8_t* bytes, std::size_t size);
bool sendToParent(const std::vector<uint8_t>& bytes);

} // namespace raylab::import
