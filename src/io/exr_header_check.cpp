#include "io/exr_header_check.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

namespace raylab {
namespace {

// Attribute names and type names are at most 255 bytes (OpenEXR's long-name limit) plus the
// terminating zero.
constexpr std::size_t kMaxNameBytes = 256;
// Headers larger than this are not images raylab writes or reads.
constexpr std::size_t kMaxHeaderBytes = 16u << 20;

} // namespace

bool checkExrHeader(const std::string& path, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot open '" + path + "': " + std::strerror(errno);
        return false;
    }
    in.seekg(0, std::ios::end);
    const auto fileSize = static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0));
    in.seekg(0);
    std::vector<char> header(std::min(fileSize, kMaxHeaderBytes));
    in.read(header.data(), static_cast<std::streamsize>(header.size()));
    const auto refuse = [&](const std::string& why) {
        error = "cannot read '" + path + "': " + why;
        return false;
    };
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(header[i]); };
    if (header.size() < 8 || byte(0) != 0x76 || byte(1) != 0x2f || byte(2) != 0x31 ||
        byte(3) != 0x01) {
        return refuse("not an OpenEXR file");
    }
    std::size_t pos = 8; // magic number and version
    // A zero-terminated string of at most kMaxNameBytes, starting at pos.
    const auto skipName = [&]() -> bool {
        for (std::size_t n = 0; n < kMaxNameBytes && pos < header.size(); ++n, ++pos) {
            if (header[pos] == '\0') {
                ++pos;
                return true;
            }
        }
        return false;
    };
    while (true) {
        if (pos >= header.size()) {
            return refuse("its header ends before it is complete");
        }
        if (header[pos] == '\0') {
            return true; // the end of the header
        }
        if (!skipName() || !skipName()) {
            return refuse("an attribute name or type that does not end");
        }
        if (pos + 4 > header.size()) {
            return refuse("its header ends inside an attribute");
        }
        const uint32_t size =
            static_cast<uint32_t>(byte(pos)) | static_cast<uint32_t>(byte(pos + 1)) << 8 |
            static_cast<uint32_t>(byte(pos + 2)) << 16 | static_cast<uint32_t>(byte(pos + 3)) << 24;
        pos += 4;
        if (size > header.size() - pos) {
            return refuse("an attribute of " + std::to_string(size) +
                          " bytes where the file holds " + std::to_string(header.size() - pos));
        }
        pos += size;
    }
}

} // namespace raylab
