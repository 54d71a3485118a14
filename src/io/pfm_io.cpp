// PFM, the Portable Float Map: "PF\n<width> <height>\n<scale>\n" then 32-bit floats, RGB per
// pixel, rows from the bottom of the image to the top. A negative scale means little-endian data.
// We write "-1.0" (little-endian, no scaling) and read either byte order and "Pf" (grey) too.

#include "io/atomic_file.h"
#include "io/file_checks.h"
#include "io/image_io.h"
#include "io/text_util.h"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace raylab {
namespace {

uint32_t byteSwap(uint32_t v) {
    return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

// Reads one whitespace-separated header token starting at pos; pos ends on the character after.
bool nextToken(const std::string& data, std::size_t& pos, std::string& token) {
    while (pos < data.size() && std::isspace(static_cast<unsigned char>(data[pos])) != 0) {
        ++pos;
    }
    const std::size_t start = pos;
    while (pos < data.size() && std::isspace(static_cast<unsigned char>(data[pos])) == 0) {
        ++pos;
    }
    token = data.substr(start, pos - start);
    return !token.empty() && token.size() < 64;
}

template <typename T> bool parseWhole(const std::string& token, T& value) {
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    return ec == std::errc() && ptr == end;
}

} // namespace

bool writePfm(const std::string& path, const Framebuffer& linear, std::string& error) {
    if (linear.width < 1 || linear.height < 1 ||
        linear.pixels.size() != static_cast<std::size_t>(linear.width) * linear.height) {
        error = "cannot write '" + path + "': invalid image size " + std::to_string(linear.width) +
                "x" + std::to_string(linear.height);
        return false;
    }
    return writeFileAtomically(
        path,
        [&linear](std::FILE* file, std::string&) {
            const std::string header = "PF\n" + std::to_string(linear.width) + " " +
                                       std::to_string(linear.height) + "\n-1.0\n";
            if (std::fwrite(header.data(), 1, header.size(), file) != header.size()) {
                return false;
            }
            std::vector<uint32_t> row(static_cast<std::size_t>(linear.width) * 3);
            for (int y = linear.height - 1; y >= 0; --y) { // bottom row first
                for (int x = 0; x < linear.width; ++x) {
                    const glm::vec3& p = linear.at(x, y);
                    for (int c = 0; c < 3; ++c) {
                        uint32_t bits = std::bit_cast<uint32_t>(p[c]);
                        if constexpr (std::endian::native == std::endian::big) {
                            bits = byteSwap(bits);
                        }
                        row[static_cast<std::size_t>(x) * 3 + static_cast<std::size_t>(c)] = bits;
                    }
                }
                if (std::fwrite(row.data(), sizeof(uint32_t), row.size(), file) != row.size()) {
                    return false;
                }
            }
            return true;
        },
        error);
}

bool readPfm(const std::string& path, Framebuffer& linear, std::string& error) {
    const SingleLineOnExit oneLine(error);
    // The largest PFM raylab reads: kMaxImageSide squared colour pixels and a header.
    constexpr std::uintmax_t kMaxPfmBytes =
        static_cast<std::uintmax_t>(kMaxImageSide) * kMaxImageSide * 3 * sizeof(float) + 4096;
    std::uintmax_t size = 0;
    if (!checkRegularFile(path, "image", kMaxPfmBytes, size, error)) {
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot open '" + path + "': " + std::strerror(errno);
        return false;
    }
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto fail = [&](const std::string& why) {
        error = "cannot read '" + path + "': " + why;
        return false;
    };
    std::size_t pos = 0;
    std::string magic, widthText, heightText, scaleText;
    if (!nextToken(data, pos, magic) || (magic != "PF" && magic != "Pf")) {
        return fail("not a PFM file");
    }
    const int channels = magic == "PF" ? 3 : 1;
    int width = 0, height = 0;
    float scale = 0.0f;
    if (!nextToken(data, pos, widthText) || !nextToken(data, pos, heightText) ||
        !nextToken(data, pos, scaleText) || !parseWhole(widthText, width) ||
        !parseWhole(heightText, height) || !parseWhole(scaleText, scale)) {
        return fail("malformed PFM header");
    }
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
        return fail("image size " + widthText + "x" + heightText + " out of range");
    }
    if (!std::isfinite(scale) || scale == 0.0f) {
        return fail("invalid PFM scale " + scaleText);
    }
    // Exactly one white-space character separates the header from the data.
    if (pos >= data.size() || std::isspace(static_cast<unsigned char>(data[pos])) == 0) {
        return fail("malformed PFM header");
    }
    ++pos;
    const std::size_t count = static_cast<std::size_t>(width) * height * channels;
    if (data.size() - pos != count * sizeof(float)) {
        return fail("expected " + std::to_string(count * sizeof(float)) + " bytes of pixels, got " +
                    std::to_string(data.size() - pos));
    }
    const bool dataLittle = scale < 0.0f;
    const bool swap = dataLittle != (std::endian::native == std::endian::little);
    Framebuffer result(width, height);
    for (std::size_t i = 0; i < count; ++i) {
        uint32_t bits = 0;
        std::memcpy(&bits, data.data() + pos + i * sizeof(float), sizeof bits);
        if (swap) {
            bits = byteSwap(bits);
        }
        const float value = std::bit_cast<float>(bits);
        const std::size_t pixel = i / static_cast<std::size_t>(channels);
        const int x = static_cast<int>(pixel % static_cast<std::size_t>(width));
        const int y = height - 1 - static_cast<int>(pixel / static_cast<std::size_t>(width));
        if (channels == 1) {
            result.at(x, y) = glm::vec3(value);
        } else {
            result.at(x, y)[static_cast<int>(i % 3)] = value;
        }
    }
    linear = std::move(result);
    return true;
}

} // namespace raylab
