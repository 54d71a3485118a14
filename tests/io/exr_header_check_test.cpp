// The look at an OpenEXR header before OpenEXR reads it: real files pass; attributes whose size
// field disagrees with what OpenEXR will read (a fixed-size type with another size, a preview
// or channel list that does not fill its size, a size past the file's end) are refused in one
// line, so OpenEXR never reads its header from the wrong place or allocates what a size claims.

#include "io/exr_header_check.h"
#include "io/image_io.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace raylab {
namespace {

namespace fs = std::filesystem;

class ExrHeaderCheck : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("raylab-exr-header-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // A file of the magic number, version 2 and `attributes`, then the header's end and `tail`.
    std::string file(const std::string& attributes,
                     const std::string& tail = std::string(64, 'x')) {
        std::string name = std::to_string(files_++); // (appended: GCC 12's -Wrestrict misfires
        name += ".exr";                              // on "h" + to_string(...) + ".exr")
        const std::string path = (dir_ / name).string();
        std::ofstream out(path, std::ios::binary);
        out << std::string("\x76\x2f\x31\x01\x02\x00\x00\x00", 8) << attributes << '\0' << tail;
        return path;
    }
    static std::string attribute(const std::string& name, const std::string& type, uint32_t size,
                                 const std::string& value) {
        std::string a = name;
        a += '\0';
        a += type;
        a += '\0';
        for (int i = 0; i < 4; ++i) {
            a += static_cast<char>((size >> (8 * i)) & 0xff);
        }
        return a + value;
    }
    static std::string le32(uint32_t v) {
        std::string s;
        for (int i = 0; i < 4; ++i) {
            s += static_cast<char>((v >> (8 * i)) & 0xff);
        }
        return s;
    }
    fs::path dir_;
    int files_ = 0;
};

TEST_F(ExrHeaderCheck, ARealFilePasses) {
    Framebuffer image;
    image.width = 3;
    image.height = 2;
    image.pixels.assign(6, glm::vec3(0.25f, 0.5f, 1.0f));
    const std::string path = (dir_ / "real.exr").string();
    std::string error;
    ASSERT_TRUE(writeImage(path, image, DisplayMode::Lab, 0.0f, error)) << error;
    EXPECT_TRUE(checkExrHeader(path, error)) << error;
}

TEST_F(ExrHeaderCheck, RightSizesPass) {
    const std::string channel = std::string("R\0", 2) + std::string(16, '\0');
    const std::string path = file(
        attribute("compression", "compression", 1, std::string(1, '\0')) +
        attribute("pixelAspectRatio", "float", 4, std::string(4, '\0')) +
        attribute("channels", "chlist", static_cast<uint32_t>(channel.size() + 1), channel + '\0') +
        attribute("preview", "preview", 8 + 4 * 2 * 3, le32(2) + le32(3) + std::string(24, 'p')) +
        attribute("comment", "string", 5, "hello"));
    std::string error;
    EXPECT_TRUE(checkExrHeader(path, error)) << error;
}

TEST_F(ExrHeaderCheck, SizesThatDisagreeWithTheValueAreRefused) {
    const std::string channel = std::string("R\0", 2) + std::string(16, '\0');
    const std::string cases[] = {
        // A compression attribute claiming 1025 bytes: OpenEXR reads 1 and goes on from there.
        attribute("compression", "compression", 1025, std::string(1025, 'c')),
        attribute("screenWindowWidth", "float", 8, std::string(8, '\0')),
        attribute("dataWindow", "box2i", 4, std::string(4, '\0')),
        // A 65535 x 65535 preview in 16 bytes: OpenEXR would allocate 17 GB.
        attribute("preview", "preview", 16, le32(65535) + le32(65535) + std::string(8, 'p')),
        // A channel list that runs past its size (no terminating empty name).
        attribute("channels", "chlist", static_cast<uint32_t>(channel.size()), channel),
        // A size past the file's end.
        attribute("comment", "string", 1u << 30, "x"),
    };
    for (const std::string& bad : cases) {
        std::string error;
        EXPECT_FALSE(checkExrHeader(file(bad), error)) << bad.substr(0, 20);
        EXPECT_NE(error.find("cannot read '"), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

} // namespace
} // namespace raylab
