#pragma once
// The file browser's part of the panel (file_browser.h's listing, drawn with Dear ImGui): the
// folder, a list of its subfolders and mesh files to click, and why a folder could not be listed.

#include "file_browser.h"

#include <string>

namespace raylab {

// Draws the browser below the current item. A click on a folder walks into it (or up, ".."); a
// click on a mesh file puts its path in `chosen` and returns true (the caller opens it).
bool drawFileBrowser(FileBrowser& browser, std::string& chosen);

} // namespace raylab
