// OpenEXR: linear RGB as three 32-bit float channels (ZIP compressed), read back into a
// Framebuffer (missing channels read as 0).

#include "io/atomic_file.h"
#include "io/exr_header_check.h"
#include "io/image_io.h"
#include "io/text_util.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <exception>

namespace raylab {
namespace {

constexpr const char* kChannels[3] = {"R", "G", "B"};

// The slices of one colour channel of a Framebuffer, displaced so that pixel (minX, minY) of the
// file's data window lands on pixels[0].
Imf::Slice channelSlice(Framebuffer& image, int channel, int minX, int minY) {
    const std::ptrdiff_t xStride = sizeof(glm::vec3);
    const std::ptrdiff_t yStride = xStride * image.width;
    char* base = reinterpret_cast<char*>(image.pixels.data()) +
                 static_cast<std::ptrdiff_t>(channel) * static_cast<std::ptrdiff_t>(sizeof(float)) -
                 minX * xStride - minY * yStride;
    return Imf::Slice(Imf::FLOAT, base, static_cast<std::size_t>(xStride),
                      static_cast<std::size_t>(yStride), 1, 1, 0.0);
}

} // namespace

bool writeExr(const std::string& path, const Framebuffer& linear, std::string& error) {
    if (linear.width < 1 || linear.height < 1 ||
        linear.pixels.size() != static_cast<std::size_t>(linear.width) * linear.height) {
        error = "cannot write '" + path + "': invalid image size " + std::to_string(linear.width) +
                "x" + std::to_string(linear.height);
        return false;
    }
    return writeFileAtomicallyByName(
        path,
        [&linear](const std::string& tempPath, std::string& bodyError) {
            try {
                Imf::Header header(linear.width, linear.height);
                for (const char* name : kChannels) {
                    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                }
                // OpenEXR only reads through the slices; the cast does not lead to a write.
                auto& pixels = const_cast<Framebuffer&>(linear);
                Imf::FrameBuffer slices;
                for (int c = 0; c < 3; ++c) {
                    slices.insert(kChannels[c], channelSlice(pixels, c, 0, 0));
                }
                Imf::OutputFile file(tempPath.c_str(), header);
                file.setFrameBuffer(slices);
                file.writePixels(linear.height);
                return true;
            } catch (const std::exception& e) {
                bodyError = e.what();
                return false;
            }
        },
        error);
}

bool readExr(const std::string& path, Framebuffer& linear, std::string& error) {
    const SingleLineOnExit oneLine(error);
    if (!checkExrHeader(path, error)) {
        return false;
    }
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
            error = "cannot read '" + path + "': image size out of range";
            return false;
        }
        Framebuffer result(static_cast<int>(width), static_cast<int>(height));
        Imf::FrameBuffer slices;
        for (int c = 0; c < 3; ++c) {
            slices.insert(kChannels[c], channelSlice(result, c, window.min.x, window.min.y));
        }
        file.setFrameBuffer(slices);
        file.readPixels(window.min.y, window.max.y);
        linear = std::move(result);
        return true;
    } catch (const std::exception& e) {
        error = "cannot read '" + path + "': " + e.what();
        return false;
    }
}

} // namespace raylab
