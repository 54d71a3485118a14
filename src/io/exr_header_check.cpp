#include "io/exr_header_check.h"

#include "io/text_util.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>
#include <vector>

namespace raylab {
namespace {

// Attribute names and type names are at most 255 bytes (OpenEXR's long-name limit) plus the
// terminating zero.
constexpr std::size_t kMaxNameBytes = 256;
// Headers larger than this are not images raylab writes or reads.
constexpr std::size_t kMaxHeaderBytes = 16u << 20;

// The size of each attribute type OpenEXR 3.1 reads as a fixed number of bytes whatever the
// attribute's size field says: a size that differs would make it read the rest of the header
// from the wrong place (names and sizes taken from inside a value). 0: not a fixed-size type.
std::size_t fixedSizeOf(std::string_view type) {
    struct Fixed {
        std::string_view type;
        std::size_t bytes;
    };
    static constexpr Fixed kFixed[] = {{"box2i", 16},      {"box2f", 16},   {"chromaticities", 32},
                                       {"compression", 1}, {"double", 8},   {"envmap", 1},
                                       {"float", 4},       {"int", 4},      {"keycode", 28},
                                       {"lineOrder", 1},   {"m33f", 36},    {"m33d", 72},
                                       {"m44f", 64},       {"m44d", 128},   {"rational", 8},
                                       {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
                                       {"v2f", 8},         {"v2d", 16},     {"v3i", 12},
                                       {"v3f", 12},        {"v3d", 24},     {"deepImageState", 1}};
    for (const Fixed& f : kFixed) {
        if (f.type == type) {
            return f.bytes;
        }
    }
    return 0;
}

uint32_t le32(const unsigned char* p) {
    return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
           static_cast<uint32_t>(p[2]) << 16 | static_cast<uint32_t>(p[3]) << 24;
}

// The bytes OpenEXR reads for a channel list (name, then 16 bytes, per channel, up to an empty
// name) starting at `value`, or SIZE_MAX when they run past `size`.
std::size_t channelListBytes(const unsigned char* value, std::size_t size) {
    std::size_t pos = 0;
    while (pos < size) {
        if (value[pos] == 0) {
            return pos + 1;
        }
        while (pos < size && value[pos] != 0) {
            ++pos;
        }
        pos += 1 + 16; // the name's zero, pixel type, pLinear and reserved, x and y sampling
    }
    return SIZE_MAX;
}

// Whether OpenEXR reads exactly `size` bytes for an attribute of `type` whose value starts at
// `value`; for the types it reads by their own structure rather than by the size field.
bool readsItsSize(std::string_view type, const unsigned char* value, std::size_t size) {
    if (const std::size_t fixed = fixedSizeOf(type); fixed != 0) {
        return size == fixed;
    }
    if (type == "preview") { // width, height, then width * height RGBA bytes
        if (size < 8) {
            return false;
        }
        const uint64_t pixels = static_cast<uint64_t>(le32(value)) * le32(value + 4);
        return pixels <= (size - 8) / 4 && 8 + 4 * pixels == size;
    }
    if (type == "chlist") {
        return channelListBytes(value, size) == size;
    }
    return true; // read by the size field: string, stringvector, floatvector, unknown types
}

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
    // A zero-terminated string of at most kMaxNameBytes, starting at pos, into `name`.
    const auto skipName = [&](std::string_view& name) -> bool {
        const std::size_t start = pos;
        for (std::size_t n = 0; n < kMaxNameBytes && pos < header.size(); ++n, ++pos) {
            if (header[pos] == '\0') {
                name = std::string_view(header.data() + start, pos - start);
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
        std::string_view name;
        std::string_view type;
        if (!skipName(name) || !skipName(type)) {
            return refuse("an attribute name or type that does not end");
        }
        if (pos + 4 > header.size()) {
            return refuse("its header ends inside an attribute");
        }
        const uint32_t size = le32(reinterpret_cast<const unsigned char*>(header.data() + pos));
        pos += 4;
        if (size > header.size() - pos) {
            return refuse("an attribute of " + std::to_string(size) +
                          " bytes where the file holds " + std::to_string(header.size() - pos));
        }
        if (!readsItsSize(type, reinterpret_cast<const unsigned char*>(header.data() + pos),
                          size)) {
            return refuse("a " + singleLine(type) + " attribute '" + singleLine(name) + "' of " +
                          std::to_string(size) + " bytes, which is not the size of its value");
        }
        pos += size;
    }
}

} // namespace raylab
