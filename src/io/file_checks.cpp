#include "io/file_checks.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace raylab {

bool checkRegularFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes,
                      std::uintmax_t& size, std::string& error) {
    std::error_code code;
    const std::filesystem::file_status status = std::filesystem::status(path, code);
    if (code) {
        error = "cannot open " + what + " '" + path + "': " + code.message();
        return false;
    }
    if (!std::filesystem::is_regular_file(status)) {
        error = what + " '" + path + "' is not a regular file";
        return false;
    }
    size = std::filesystem::file_size(path, code);
    if (code) {
        error = "cannot read " + what + " '" + path + "': " + code.message();
        return false;
    }
    if (size > maxBytes) {
        error = what + " '" + path + "' is larger than " + std::to_string(maxBytes >> 20) + " MiB";
        return false;
    }
    return true;
}

bool readRegularTextFile(const std::string& path, const std::string& what, std::uintmax_t maxBytes,
                         std::string& text, std::string& error) {
    std::uintmax_t size = 0;
    if (!checkRegularFile(path, what, maxBytes, size, error)) {
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot open " + what + " '" + path + "': " + std::strerror(errno);
        return false;
    }
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) {
        error = "cannot read " + what + " '" + path + "': " + std::strerror(errno);
        return false;
    }
    return true;
}

} // namespace raylab
