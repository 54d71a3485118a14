#pragma once
// A first look at an OpenEXR file's header before OpenEXR reads it. OpenEXR 3.1 allocates what
// an attribute's size field says before it knows whether the file holds that many bytes, so a
// 2 KiB file that claims a 2 GiB attribute takes 2 GiB. This walks the header's attributes
// (name, type, size, value) and refuses sizes the file cannot hold.

#include <string>

namespace raylab {

// Returns true when `path` starts with the OpenEXR magic number and every header attribute fits
// inside the file; else false with one line in `error` naming the file.
bool checkExrHeader(const std::string& path, std::string& error);

} // namespace raylab
