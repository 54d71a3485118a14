#pragma once
// Image files: PNG (8-bit, display-transformed), PFM (linear float RGB) and EXR (linear half/float
// RGB). Every writer writes a temporary file beside the target and renames it, so a failed write
// never leaves a partial file.

#include "core/render/framebuffer.h"
#include "core/render_settings.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace raylab {

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> pixels; // RGBA, row-major from the top
};

// Writes a linear image by the path's extension: .png (display transform of settings), .pfm, .exr.
// textChunks go into PNG tEXt chunks (ignored by the other formats).
bool writeImage(const std::string& path, const Framebuffer& linear, DisplayMode display,
                float exposure, std::string& error,
                const std::map<std::string, std::string>& textChunks = {});

bool writePng(const std::string& path, const Rgba8Image& image, std::string& error,
              const std::map<std::string, std::string>& textChunks = {});
bool readPng(const std::string& path, Rgba8Image& image, std::string& error,
             std::map<std::string, std::string>* textChunks = nullptr);

// PFM stores rows bottom to top; these functions convert to and from top-to-bottom Framebuffers.
bool writePfm(const std::string& path, const Framebuffer& linear, std::string& error);
bool readPfm(const std::string& path, Framebuffer& linear, std::string& error);

// OpenEXR, three 32-bit float channels R, G, B. readExr reads any RGB(A) EXR (other channels are
// ignored, missing ones are 0).
bool writeExr(const std::string& path, const Framebuffer& linear, std::string& error);
bool readExr(const std::string& path, Framebuffer& linear, std::string& error);

// True for the extensions writeImage understands (case-insensitive): .png, .pfm, .exr.
bool isSupportedImagePath(const std::string& path);
// Why isSupportedImagePath is false, as the end of an error line: "unsupported image format
// '.jpg' (use .png, .pfm or .exr)".
std::string unsupportedImageReason(const std::string& path);

} // namespace raylab
