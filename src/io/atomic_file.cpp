#include "io/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace raylab {
namespace {

std::string systemError(const std::string& what, const std::string& path, int err) {
    return "cannot " + what + " '" + path + "': " + std::strerror(err);
}

// Creates an empty temporary file beside `path` (".<name>.tmp-XXXXXX"); returns its descriptor or
// -1 with errno set. The name is written to tempPath.
int makeTemp(const std::string& path, std::string& tempPath) {
    const std::filesystem::path target(path);
    std::filesystem::path dir = target.parent_path();
    const std::string name = target.filename().string();
    if (name.empty()) {
        errno = EISDIR;
        return -1;
    }
    const std::filesystem::path temp = dir / ("." + name + ".tmp-XXXXXX");
    const std::string pattern = temp.string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const int fd = ::mkstemp(buffer.data());
    if (fd >= 0) {
        ::fchmod(fd, 0644);
        tempPath = buffer.data();
    }
    return fd;
}

// A path that exists and is a folder cannot be replaced by a file.
bool isDirectory(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// Opens a new temporary file beside `path`, which must not be a folder; returns its descriptor, or
// -1 with a one-line error naming `path`.
int openTempBeside(const std::string& path, std::string& tempPath, std::string& error) {
    if (isDirectory(path)) {
        error = systemError("write", path, EISDIR);
        return -1;
    }
    const int fd = makeTemp(path, tempPath);
    if (fd < 0) {
        error = systemError("write", path, errno);
    }
    return fd;
}

bool finish(const std::string& path, const std::string& tempPath, std::string& error) {
    if (std::rename(tempPath.c_str(), path.c_str()) != 0) {
        error = systemError("write", path, errno);
        std::remove(tempPath.c_str());
        return false;
    }
    return true;
}

} // namespace

bool writeFileAtomically(const std::string& path,
                         const std::function<bool(std::FILE* file, std::string& error)>& writeBody,
                         std::string& error) {
    std::string tempPath;
    const int fd = openTempBeside(path, tempPath, error);
    if (fd < 0) {
        return false;
    }
    std::FILE* file = ::fdopen(fd, "wb");
    if (file == nullptr) {
        error = systemError("write", path, errno);
        ::close(fd);
        std::remove(tempPath.c_str());
        return false;
    }
    std::string bodyError;
    bool ok = writeBody(file, bodyError);
    int err = 0;
    if (ok && (std::fflush(file) != 0 || std::ferror(file) != 0)) {
        err = errno;
        ok = false;
    }
    if (std::fclose(file) != 0 && ok) {
        err = errno;
        ok = false;
    }
    if (!ok) {
        error = !bodyError.empty() ? "cannot write '" + path + "': " + bodyError
                                   : systemError("write", path, err != 0 ? err : EIO);
        std::remove(tempPath.c_str());
        return false;
    }
    return finish(path, tempPath, error);
}

bool writeFileAtomicallyByName(
    const std::string& path,
    const std::function<bool(const std::string& tempPath, std::string& error)>& writeTo,
    std::string& error) {
    std::string tempPath;
    const int fd = openTempBeside(path, tempPath, error);
    if (fd < 0) {
        return false;
    }
    ::close(fd);
    std::string bodyError;
    if (!writeTo(tempPath, bodyError)) {
        error = "cannot write '" + path + "': " + (bodyError.empty() ? "unknown error" : bodyError);
        std::remove(tempPath.c_str());
        return false;
    }
    return finish(path, tempPath, error);
}

bool checkWritable(const std::string& path, std::string& error) {
    std::string tempPath;
    const int fd = openTempBeside(path, tempPath, error);
    if (fd < 0) {
        return false;
    }
    ::close(fd);
    std::remove(tempPath.c_str());
    return true;
}

} // namespace raylab
