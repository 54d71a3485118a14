// Picks the image format by the path's extension.

#include "io/image_io.h"

#include "core/render/display_transform.h"
#include "io/text_util.h"

#include <filesystem>

namespace raylab {

bool isSupportedImagePath(const std::string& path) {
    const std::string ext = extensionOf(path);
    return ext == ".png" || ext == ".pfm" || ext == ".exr";
}

bool writeImage(const std::string& path, const Framebuffer& linear, DisplayMode display,
                float exposure, std::string& error,
                const std::map<std::string, std::string>& textChunks) {
    const std::string ext = extensionOf(path);
    if (ext == ".pfm") {
        return writePfm(path, linear, error);
    }
    if (ext == ".exr") {
        return writeExr(path, linear, error);
    }
    if (ext == ".png") {
        if (linear.width < 1 || linear.height < 1 ||
            linear.pixels.size() != static_cast<std::size_t>(linear.width) * linear.height) {
            error = "cannot write '" + path + "': invalid image size";
            return false;
        }
        Rgba8Image image;
        image.width = linear.width;
        image.height = linear.height;
        image.pixels = toRgba8(linear, display, exposure);
        return writePng(path, image, error, textChunks);
    }
    error = "cannot write '" + path + "': " + unsupportedImageReason(path);
    return false;
}

std::string unsupportedImageReason(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    return (ext.empty() ? std::string("no file extension")
                        : "unsupported image format '" + ext + "'") +
           " (use .png, .pfm or .exr)";
}

} // namespace raylab
