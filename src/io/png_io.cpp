// PNG through libpng: 8-bit RGBA out, any PNG in (expanded to 8-bit RGBA), tEXt/iTXt chunks both
// ways. libpng reports errors with longjmp, so the functions that call setjmp keep every object
// they touch after it outside their own frame (in the job structs passed by reference).

#include "io/atomic_file.h"
#include "io/image_io.h"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <png.h>
#include <vector>

namespace raylab {
namespace {

constexpr png_uint_32 kMaxPngChunks = 256;

// Walks the chunks of the PNG in `file` (whose first 8 bytes, the signature, were read): every
// chunk's length must fit in what the file holds. libpng takes (and clears) the room a text
// chunk's length field claims before it reads the chunk, so a 1 KB file claiming a 1.8 GB tEXt
// chunk would take 1.8 GB. Returns an empty string, or why the file is refused. Leaves the file
// just after the signature.
std::string checkPngChunks(std::FILE* file) {
    if (std::fseek(file, 0, SEEK_END) != 0) {
        return "cannot seek in it";
    }
    const long size = std::ftell(file);
    long pos = 8;
    std::string problem;
    while (pos < size && problem.empty()) {
        unsigned char header[8];
        if (std::fseek(file, pos, SEEK_SET) != 0 || std::fread(header, 1, 8, file) != 8) {
            problem = "it ends inside a chunk's header";
            break;
        }
        const unsigned long length = png_get_uint_32(header);
        const long room = size - pos - 12; // the chunk's data, after its header, before its CRC
        if (room < 0 || length > static_cast<unsigned long>(room)) {
            std::string type;
            for (int i = 4; i < 8; ++i) {
                type += header[i] >= 32 && header[i] < 127 ? static_cast<char>(header[i]) : '?';
            }
            problem = "a " + type + " chunk of " + std::to_string(length) +
                      " bytes where the file holds " + std::to_string(room < 0 ? 0 : room);
            break;
        }
        if (std::memcmp(header + 4, "IEND", 4) == 0) {
            break;
        }
        pos += 12 + static_cast<long>(length);
    }
    std::fseek(file, 8, SEEK_SET);
    return problem;
}

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    if (auto* error = static_cast<std::string*>(png_get_error_ptr(png)); error != nullptr) {
        *error = message != nullptr ? message : "libpng error";
    }
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

// PNG keywords: 1 to 79 printable Latin-1 characters, no leading, trailing or double spaces.
bool isValidKeyword(const std::string& key) {
    if (key.empty() || key.size() > 79 || key.front() == ' ' || key.back() == ' ' ||
        key.find("  ") != std::string::npos) {
        return false;
    }
    for (const char c : key) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 32 || (u > 126 && u < 161)) {
            return false;
        }
    }
    return true;
}

bool isAscii(const std::string& text) {
    for (const char c : text) {
        if (static_cast<unsigned char>(c) >= 128) {
            return false;
        }
    }
    return true;
}

struct WriteJob {
    const Rgba8Image& image;
    std::vector<png_text> texts;
    std::string error;
};

bool writePngTo(std::FILE* file, WriteJob& job) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &job.error, onPngError, onPngWarning);
    if (png == nullptr) {
        job.error = "out of memory";
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_write_struct(&png, nullptr);
        job.error = "out of memory";
        return false;
    }
    if (setjmp(png_jmpbuf(png)) != 0) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(job.image.width),
                 static_cast<png_uint_32>(job.image.height), 8, PNG_COLOR_TYPE_RGB_ALPHA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!job.texts.empty()) {
        png_set_text(png, info, job.texts.data(), static_cast<int>(job.texts.size()));
    }
    png_write_info(png, info);
    const std::size_t stride = static_cast<std::size_t>(job.image.width) * 4;
    for (int y = 0; y < job.image.height; ++y) {
        png_write_row(png, job.image.pixels.data() + stride * static_cast<std::size_t>(y));
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

struct ReadJob {
    std::FILE* file;
    Rgba8Image image;
    std::vector<png_bytep> rows;
    std::map<std::string, std::string> texts;
    std::string error;
};

bool readPngFrom(ReadJob& job) {
    png_structp png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &job.error, onPngError, onPngWarning);
    if (png == nullptr) {
        job.error = "out of memory";
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        job.error = "out of memory";
        return false;
    }
    if (setjmp(png_jmpbuf(png)) != 0) {
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_init_io(png, job.file);
    png_set_sig_bytes(png, 8);
    png_set_user_limits(png, kMaxImageSide, kMaxImageSide);
    // At most kMaxPngChunks ancillary chunks are kept (readPng checked every chunk's length
    // against the file before libpng runs: checkPngChunks).
    png_set_chunk_cache_max(png, kMaxPngChunks);
    png_read_info(png, info);

    png_set_expand(png); // palette to RGB, grey below 8 bits to 8, tRNS to alpha
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    if ((png_get_color_type(png, info) & PNG_COLOR_MASK_ALPHA) == 0 &&
        png_get_valid(png, info, PNG_INFO_tRNS) == 0) {
        png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    }
    png_set_interlace_handling(png);
    png_read_update_info(png, info);

    job.image.width = static_cast<int>(png_get_image_width(png, info));
    job.image.height = static_cast<int>(png_get_image_height(png, info));
    const std::size_t stride = static_cast<std::size_t>(job.image.width) * 4;
    if (png_get_rowbytes(png, info) != stride) {
        job.error = "unexpected PNG layout";
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    job.image.pixels.resize(stride * static_cast<std::size_t>(job.image.height));
    job.rows.resize(static_cast<std::size_t>(job.image.height));
    for (std::size_t y = 0; y < job.rows.size(); ++y) {
        job.rows[y] = job.image.pixels.data() + stride * y;
    }
    png_read_image(png, job.rows.data());
    png_read_end(png, info); // text chunks after the image data land in info too

    png_textp text = nullptr;
    const int count = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < count; ++i) {
        const std::size_t length = text[i].compression >= PNG_ITXT_COMPRESSION_NONE
                                       ? text[i].itxt_length
                                       : text[i].text_length;
        job.texts[text[i].key] =
            text[i].text != nullptr ? std::string(text[i].text, length) : std::string();
    }
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

} // namespace

bool writePng(const std::string& path, const Rgba8Image& image, std::string& error,
              const std::map<std::string, std::string>& textChunks) {
    if (image.width < 1 || image.height < 1 || image.width > kMaxImageSide ||
        image.height > kMaxImageSide ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
        error = "cannot write '" + path + "': invalid image size " + std::to_string(image.width) +
                "x" + std::to_string(image.height);
        return false;
    }
    WriteJob job{image, {}, {}};
    for (const auto& [key, value] : textChunks) {
        if (!isValidKeyword(key) || value.find('\0') != std::string::npos) {
            error = "cannot write '" + path + "': invalid PNG text key '" + key + "'";
            return false;
        }
        png_text chunk{};
        chunk.key = const_cast<char*>(key.c_str()); // libpng copies and never writes these
        chunk.text = const_cast<char*>(value.c_str());
        if (isAscii(value)) {
            chunk.compression = PNG_TEXT_COMPRESSION_NONE; // tEXt
            chunk.text_length = value.size();
        } else {
            chunk.compression = PNG_ITXT_COMPRESSION_NONE; // iTXt: UTF-8
            chunk.itxt_length = value.size();
        }
        job.texts.push_back(chunk);
    }
    return writeFileAtomically(
        path,
        [&job](std::FILE* file, std::string& bodyError) {
            if (!writePngTo(file, job)) {
                bodyError = job.error;
                return false;
            }
            return true;
        },
        error);
}

bool readPng(const std::string& path, Rgba8Image& image, std::string& error,
             std::map<std::string, std::string>* textChunks) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        error = "cannot open '" + path + "': " + std::strerror(errno);
        return false;
    }
    unsigned char signature[8] = {};
    if (std::fread(signature, 1, sizeof signature, file) != sizeof signature ||
        png_sig_cmp(signature, 0, sizeof signature) != 0) {
        std::fclose(file);
        error = "cannot read '" + path + "': not a PNG file";
        return false;
    }
    if (const std::string problem = checkPngChunks(file); !problem.empty()) {
        std::fclose(file);
        error = "cannot read '" + path + "': " + problem;
        return false;
    }
    ReadJob job{file, {}, {}, {}, {}};
    const bool ok = readPngFrom(job);
    std::fclose(file);
    if (!ok) {
        error = "cannot read '" + path + "': " + job.error;
        return false;
    }
    image = std::move(job.image);
    if (textChunks != nullptr) {
        *textChunks = std::move(job.texts);
    }
    return true;
}

} // namespace raylab
