#pragma once
// The panel's file browser ("Browse" beside the path field): the subfolders and mesh files of one
// folder, to walk through and pick a mesh from. GL-free; the panel draws it (panel.cpp).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct BrowserEntry {
    std::string name;         // the file or folder name; ".." for the parent folder
    bool folder = false;      // a folder (or a link to one)
    std::uintmax_t bytes = 0; // a file's size
};

class FileBrowser {
public:
    // The most entries listed; a folder with more says how many were left out.
    static constexpr std::size_t kMaxEntries = 2000;

    // Lists `folder` (made absolute and normal). Returns false, with error() saying why in one
    // line, when it cannot be read; the previous listing is then kept.
    bool open(const std::filesystem::path& folder);
    // The folder to start in for a path field holding `fieldPath`: the folder of that file, or
    // that folder, when it exists; else the working directory.
    static std::filesystem::path startFolder(const std::string& fieldPath);

    const std::filesystem::path& folder() const { return folder_; }
    // ".." first when the folder has a parent, then the subfolders, then the mesh files
    // (io/mesh_formats.h), each group by name ignoring case. Hidden entries (a leading dot) and
    // entries that cannot be examined are left out.
    const std::vector<BrowserEntry>& entries() const { return entries_; }
    std::size_t leftOut() const { return leftOut_; } // beyond kMaxEntries
    const std::string& error() const { return error_; }

    // Picks entries()[i]: a folder is opened (returns false; error() says when it could not be),
    // a file's full path is put in `chosen` (returns true).
    bool choose(std::size_t i, std::string& chosen);

private:
    std::filesystem::path folder_;
    std::vector<BrowserEntry> entries_;
    std::size_t leftOut_ = 0;
    std::string error_;
};

} // namespace raylab
