#include "file_browser.h"

#include "io/mesh_formats.h"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace raylab {

namespace fs = std::filesystem;

namespace {

bool lessIgnoringCase(const std::string& a, const std::string& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        [](unsigned char x, unsigned char y) {
                                            const int lx = std::tolower(x);
                                            const int ly = std::tolower(y);
                                            return lx != ly ? lx < ly : x < y;
                                        });
}

} // namespace

bool FileBrowser::open(const fs::path& folder) {
    std::error_code ec;
    fs::path absolute = fs::absolute(folder, ec).lexically_normal();
    if (!absolute.has_filename() && absolute.has_relative_path()) {
        absolute = absolute.parent_path(); // "dir/" is "dir"
    }
    fs::directory_iterator it(ec ? folder : absolute, ec);
    if (ec) {
        error_ = "cannot list '" + absolute.string() + "': " + ec.message();
        return false;
    }
    std::vector<BrowserEntry> folders;
    std::vector<BrowserEntry> files;
    std::size_t seen = 0;
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) {
            break; // an entry that vanished or cannot be read ends the listing here
        }
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') {
            continue;
        }
        std::error_code entryError;
        const bool isFolder = it->is_directory(entryError); // follows links
        if (entryError) {
            continue;
        }
        BrowserEntry entry{name, isFolder, 0};
        if (!isFolder) {
            if (!isMeshFileName(name) || !it->is_regular_file(entryError) || entryError) {
                continue;
            }
            entry.bytes = it->file_size(entryError);
        }
        if (++seen > kMaxEntries) {
            continue;
        }
        (isFolder ? folders : files).push_back(std::move(entry));
    }
    const auto byName = [](const BrowserEntry& a, const BrowserEntry& b) {
        return lessIgnoringCase(a.name, b.name);
    };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    entries_.clear();
    if (absolute.has_relative_path()) { // not the root
        entries_.push_back(BrowserEntry{"..", true, 0});
    }
    entries_.insert(entries_.end(), folders.begin(), folders.end());
    entries_.insert(entries_.end(), files.begin(), files.end());
    leftOut_ = seen > kMaxEntries ? seen - kMaxEntries : 0;
    folder_ = absolute;
    error_.clear();
    return true;
}

fs::path FileBrowser::startFolder(const std::string& fieldPath) {
    std::error_code ec;
    if (!fieldPath.empty()) {
        const fs::path given(fieldPath);
        if (fs::is_directory(given, ec)) {
            return given;
        }
        if (given.has_parent_path() && fs::is_directory(given.parent_path(), ec)) {
            return given.parent_path();
        }
    }
    const fs::path here = fs::current_path(ec);
    return ec ? fs::path("/") : here;
}

bool FileBrowser::choose(std::size_t i, std::string& chosen) {
    if (i >= entries_.size()) {
        return false;
    }
    const BrowserEntry entry = entries_[i];
    if (entry.folder) {
        open(entry.name == ".." ? folder_.parent_path() : folder_ / entry.name);
        return false;
    }
    chosen = (folder_ / entry.name).string();
    return true;
}

} // namespace raylab
