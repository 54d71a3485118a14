#include "io/partial_file.h"

#include "core/cornell_box.h"
#include "core/render_settings.h"
#include "io/atomic_file.h"
#include "io/exr_header_check.h"
#include "io/text_util.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <unistd.h>

namespace raylab {
namespace {

constexpr int kPartialVersion = 1;
constexpr const char* kColour[3] = {"R", "G", "B"};
constexpr int kWords = 4; // 32-bit words of one exact sum

std::string wordChannel(int c, int k) {
    return std::string("raylab.") + kColour[c] + "." + std::to_string(k);
}
std::string squareChannel(int c) { return std::string("raylab.") + kColour[c] + "2"; }

// The pixels' values laid out for OpenEXR's slices: per pixel, 3 approximate sums, 12 words of
// exact sums and 3 squares.
struct PixelRecord {
    float approximate[3];
    uint32_t words[3][kWords];
    float square[3];
};

template <typename T>
Imf::Slice slice(Imf::PixelType type, T* first, const Imath::Box2i& data, int width) {
    const std::ptrdiff_t xStride = sizeof(PixelRecord);
    const std::ptrdiff_t yStride = xStride * width;
    char* base = reinterpret_cast<char*>(first) - data.min.x * xStride - data.min.y * yStride;
    return Imf::Slice(type, base, static_cast<std::size_t>(xStride),
                      static_cast<std::size_t>(yStride));
}

void insertSlices(Imf::FrameBuffer& slices, std::vector<PixelRecord>& records,
                  const Imath::Box2i& data, int width, bool squares) {
    for (int c = 0; c < 3; ++c) {
        slices.insert(kColour[c], slice(Imf::FLOAT, &records[0].approximate[c], data, width));
        for (int k = 0; k < kWords; ++k) {
            slices.insert(wordChannel(c, k),
                          slice(Imf::UINT, &records[0].words[c][k], data, width));
        }
        if (squares) {
            slices.insert(squareChannel(c), slice(Imf::FLOAT, &records[0].square[c], data, width));
        }
    }
}

const std::string* stringAttribute(const Imf::Header& header, const char* name) {
    const auto* attribute = header.findTypedAttribute<Imf::StringAttribute>(name);
    return attribute ? &attribute->value() : nullptr;
}

const int* intAttribute(const Imf::Header& header, const char* name) {
    const auto* attribute = header.findTypedAttribute<Imf::IntAttribute>(name);
    return attribute ? &attribute->value() : nullptr;
}

} // namespace

PartialRender partialOf(const Film& film, int imageWidth, int imageHeight) {
    PartialRender partial;
    partial.imageWidth = imageWidth;
    partial.imageHeight = imageHeight;
    partial.window = film.window();
    partial.firstSample = film.firstSample();
    partial.endSample = film.nextSample();
    partial.sums.resize(film.pixelCount());
    for (std::size_t i = 0; i < film.pixelCount(); ++i) {
        partial.sums[i] = film.sumOf(i);
    }
    const auto squares = film.squares();
    partial.squares.assign(squares.begin(), squares.end());
    return partial;
}

bool writePartial(const std::string& path, const PartialRender& partial, std::string& error) {
    const FilmWindow& w = partial.window;
    const std::size_t pixels = static_cast<std::size_t>(w.width()) * w.height();
    if (w.width() < 1 || w.height() < 1 || w.x0 < 0 || w.y0 < 0 || w.x1 > partial.imageWidth ||
        w.y1 > partial.imageHeight || partial.sums.size() != pixels ||
        (!partial.squares.empty() && partial.squares.size() != pixels) ||
        partial.firstSample >= partial.endSample) {
        error = "cannot write '" + path + "': an empty or inconsistent partial render";
        return false;
    }
    const bool squares = !partial.squares.empty();
    std::vector<PixelRecord> records(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            const FixedSum sum = partial.sums[i].channel[c];
            records[i].approximate[c] = static_cast<float>(fromFixed(sum));
            const auto bits = static_cast<FixedSumBits>(sum);
            for (int k = 0; k < kWords; ++k) {
                records[i].words[c][k] = static_cast<uint32_t>(bits >> (32 * k));
            }
            records[i].square[c] = squares ? partial.squares[i][c] : 0.0f;
        }
    }
    return writeFileAtomicallyByName(
        path,
        [&](const std::string& tempPath, std::string& bodyError) {
            try {
                const Imath::Box2i display(
                    Imath::V2i(0, 0), Imath::V2i(partial.imageWidth - 1, partial.imageHeight - 1));
                const Imath::Box2i data(Imath::V2i(w.x0, w.y0), Imath::V2i(w.x1 - 1, w.y1 - 1));
                Imf::Header header(display, data);
                for (int c = 0; c < 3; ++c) {
                    header.channels().insert(kColour[c], Imf::Channel(Imf::FLOAT));
                    for (int k = 0; k < kWords; ++k) {
                        header.channels().insert(wordChannel(c, k), Imf::Channel(Imf::UINT));
                    }
                    if (squares) {
                        header.channels().insert(squareChannel(c), Imf::Channel(Imf::FLOAT));
                    }
                }
                header.insert("raylab.partial", Imf::IntAttribute(kPartialVersion));
                header.insert("raylab.firstSample",
                              Imf::IntAttribute(static_cast<int>(partial.firstSample)));
                header.insert("raylab.endSample",
                              Imf::IntAttribute(static_cast<int>(partial.endSample)));
                header.insert("raylab.settings", Imf::StringAttribute(partial.settingsJson));
                header.insert("raylab.scene", Imf::StringAttribute(partial.scene));
                header.insert("raylab.sceneHash", Imf::StringAttribute(partial.sceneHash));
                Imf::FrameBuffer slices;
                insertSlices(slices, records, data, w.width(), squares);
                Imf::OutputFile file(tempPath.c_str(), header);
                file.setFrameBuffer(slices);
                file.writePixels(w.height());
                return true;
            } catch (const std::exception& e) {
                bodyError = e.what();
                return false;
            }
        },
        error);
}

bool readPartial(const std::string& path, PartialRender& partial, std::string& error,
                 PartialRead what) {
    const SingleLineOnExit oneLine(error);
    if (!checkExrHeader(path, error)) {
        return false;
    }
    const auto refuse = [&](const std::string& why) {
        error = "'" + path + "': " + why;
        return false;
    };
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const int* version = intAttribute(header, "raylab.partial");
        if (!version) {
            return refuse("not a raylab partial render (no raylab.partial attribute)");
        }
        if (*version != kPartialVersion) {
            return refuse("partial render version " + std::to_string(*version) +
                          ", this raylab reads version " + std::to_string(kPartialVersion));
        }
        const int* first = intAttribute(header, "raylab.firstSample");
        const int* end = intAttribute(header, "raylab.endSample");
        const std::string* settings = stringAttribute(header, "raylab.settings");
        const std::string* scene = stringAttribute(header, "raylab.scene");
        const std::string* sceneHash = stringAttribute(header, "raylab.sceneHash");
        if (!first || !end || !settings || !scene || !sceneHash) {
            return refuse("a partial render without its sample range, settings or scene");
        }
        if (*first < 0 || *end <= *first) {
            return refuse("bad sample range " + std::to_string(*first) + ":" +
                          std::to_string(*end));
        }
        const Imath::Box2i display = header.displayWindow();
        const Imath::Box2i data = header.dataWindow();
        const long long imageWidth = static_cast<long long>(display.max.x) + 1;
        const long long imageHeight = static_cast<long long>(display.max.y) + 1;
        if (display.min.x != 0 || display.min.y != 0 || imageWidth < 1 || imageHeight < 1 ||
            imageWidth > kMaxImageSide || imageHeight > kMaxImageSide) {
            return refuse("picture size out of range");
        }
        if (data.min.x < 0 || data.min.y < 0 || data.max.x >= imageWidth ||
            data.max.y >= imageHeight || data.max.x < data.min.x || data.max.y < data.min.y) {
            return refuse("its pixels lie outside its picture");
        }
        // A forged header may claim a picture the file cannot hold: what reading it takes is
        // checked against the machine's memory before anything is allocated.
        const double pixelsClaimed = static_cast<double>(data.max.x - data.min.x + 1) *
                                     static_cast<double>(data.max.y - data.min.y + 1);
        const double bytesNeeded =
            pixelsClaimed *
            static_cast<double>(sizeof(PixelRecord) + sizeof(PixelSum) + sizeof(glm::vec3));
        const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                              static_cast<double>(sysconf(_SC_PAGESIZE));
        if (memory > 0.0 && bytesNeeded > 0.5 * memory) {
            char text[64];
            std::snprintf(text, sizeof text, "%.1f GiB", bytesNeeded / (1024.0 * 1024 * 1024));
            return refuse(std::string("reading its pixels needs ") + text +
                          ", more than half of this machine's memory");
        }
        const bool squares = header.channels().findChannel(squareChannel(0)) != nullptr;
        for (int c = 0; c < 3; ++c) {
            for (int k = 0; k < kWords; ++k) {
                const Imf::Channel* channel = header.channels().findChannel(wordChannel(c, k));
                if (!channel || channel->type != Imf::UINT) {
                    return refuse("channel " + wordChannel(c, k) + " is missing");
                }
            }
        }
        PartialRender result;
        result.imageWidth = static_cast<int>(imageWidth);
        result.imageHeight = static_cast<int>(imageHeight);
        result.window = FilmWindow{data.min.x, data.min.y, data.max.x + 1, data.max.y + 1};
        result.firstSample = static_cast<uint32_t>(*first);
        result.endSample = static_cast<uint32_t>(*end);
        result.settingsJson = *settings;
        result.scene = *scene;
        result.sceneHash = *sceneHash;
        result.hasSquares = squares;
        if (what == PartialRead::HeaderOnly) {
            partial = std::move(result);
            return true;
        }
        // Rows are read a block at a time and kept as they arrive, so that a file which claims
        // more rows than it holds fails before memory for all of them is taken.
        constexpr int kRowsPerBlock = 16;
        const int width = result.window.width();
        std::vector<PixelRecord> records(static_cast<std::size_t>(width) * kRowsPerBlock);
        for (int y0 = data.min.y; y0 <= data.max.y; y0 += kRowsPerBlock) {
            const int y1 = std::min(y0 + kRowsPerBlock - 1, data.max.y);
            const Imath::Box2i block(Imath::V2i(data.min.x, y0), Imath::V2i(data.max.x, y1));
            Imf::FrameBuffer slices;
            insertSlices(slices, records, block, width, squares);
            file.setFrameBuffer(slices);
            file.readPixels(y0, y1);
            const std::size_t count = static_cast<std::size_t>(width) * (y1 - y0 + 1);
            for (std::size_t i = 0; i < count; ++i) {
                PixelSum sum;
                for (int c = 0; c < 3; ++c) {
                    FixedSumBits bits = 0;
                    for (int k = 0; k < kWords; ++k) {
                        bits |= static_cast<FixedSumBits>(records[i].words[c][k]) << (32 * k);
                    }
                    sum.channel[c] = static_cast<FixedSum>(bits);
                }
                result.sums.push_back(sum);
                if (squares) {
                    result.squares.emplace_back(records[i].square[0], records[i].square[1],
                                                records[i].square[2]);
                }
            }
        }
        partial = std::move(result);
        return true;
    } catch (const std::exception& e) {
        return refuse(e.what());
    }
}

bool sceneContentHash(const std::string& scene, std::string& hash, std::string& error) {
    if (isLabBoxName(scene)) {
        hash = "lab box";
        return true;
    }
    std::ifstream in(scene, std::ios::binary);
    if (!in) {
        error = "cannot read '" + scene + "' to hash it";
        return false;
    }
    uint64_t h = 0xcbf29ce484222325ULL;
    char buffer[1 << 16];
    while (in) {
        in.read(buffer, sizeof buffer);
        const std::streamsize got = in.gcount();
        for (std::streamsize i = 0; i < got; ++i) {
            h = (h ^ static_cast<unsigned char>(buffer[i])) * 0x100000001b3ULL;
        }
    }
    if (in.bad()) {
        error = "cannot read '" + scene + "' to hash it";
        return false;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    hash = text;
    return true;
}

} // namespace raylab
