// Image files: PNG round trip with text chunks, PFM bit-exact with its bottom-to-top rows, EXR
// round trip, and failed writes that name the path and leave nothing behind.

#include "core/render/display_transform.h"
#include "io/image_io.h"
#include "temp_dir_test.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <limits>
#include <random>

namespace raylab {
namespace {

namespace fs = std::filesystem;

using ImageIoTest = test::TempDirTest;

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A small image whose every pixel differs, including values outside [0, 1], negative zero, and
// denormals, so that any reordering or conversion shows.
Framebuffer testImage(int w, int h) {
    Framebuffer fb(w, h);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> dist(-2.0f, 50.0f);
    for (auto& p : fb.pixels) {
        p = glm::vec3(dist(rng), dist(rng), dist(rng));
    }
    fb.at(0, 0) = glm::vec3(-0.0f, std::numeric_limits<float>::denorm_min(), 1e30f);
    return fb;
}

TEST_F(ImageIoTest, PngRoundTripWithTextChunks) {
    Rgba8Image image;
    image.width = 7;
    image.height = 3;
    for (int i = 0; i < image.width * image.height * 4; ++i) {
        image.pixels.push_back(static_cast<uint8_t>(i * 37 + 11));
    }
    const std::map<std::string, std::string> text = {{"Software", "raylab"},
                                                     {"raylab settings", "{\"threads\": 0}"},
                                                     {"Comment", "caf\xc3\xa9"}};
    std::string error;
    ASSERT_TRUE(writePng(path("a.png"), image, error, text)) << error;
    EXPECT_EQ(files(), std::vector<std::string>{"a.png"});

    Rgba8Image back;
    std::map<std::string, std::string> backText;
    ASSERT_TRUE(readPng(path("a.png"), back, error, &backText)) << error;
    EXPECT_EQ(back.width, 7);
    EXPECT_EQ(back.height, 3);
    EXPECT_EQ(back.pixels, image.pixels);
    EXPECT_EQ(backText, text);
}

TEST_F(ImageIoTest, PngFromLinearUsesTheDisplayTransform) {
    Framebuffer fb(2, 1);
    fb.at(0, 0) = glm::vec3(0.5f, 2.0f, -1.0f);
    fb.at(1, 0) = glm::vec3(0.25f);
    std::string error;
    ASSERT_TRUE(writeImage(path("lab.png"), fb, DisplayMode::Lab, 0.0f, error)) << error;
    Rgba8Image back;
    ASSERT_TRUE(readPng(path("lab.png"), back, error)) << error;
    const std::vector<uint8_t> expected = toRgba8(fb, DisplayMode::Lab, 0.0f);
    EXPECT_EQ(back.pixels, expected);
    EXPECT_EQ(back.pixels[0], 128); // round(0.5 * 255)
    EXPECT_EQ(back.pixels[1], 255); // clamped
    EXPECT_EQ(back.pixels[2], 0);
    EXPECT_EQ(back.pixels[3], 255);
}

TEST_F(ImageIoTest, PngRejectsBadKeysAndSizes) {
    Rgba8Image image;
    image.width = 1;
    image.height = 1;
    image.pixels = {1, 2, 3, 4};
    std::string error;
    EXPECT_FALSE(writePng(path("k.png"), image, error, {{"", "x"}}));
    EXPECT_FALSE(writePng(path("k.png"), image, error, {{std::string(80, 'k'), "x"}}));
    image.pixels.pop_back();
    EXPECT_FALSE(writePng(path("k.png"), image, error));
    EXPECT_NE(error.find(path("k.png")), std::string::npos) << error;
    EXPECT_TRUE(files().empty());
}

TEST_F(ImageIoTest, ReadPngRejectsGarbageAndTruncation) {
    std::string error;
    Rgba8Image back;
    std::ofstream(path("g.png"), std::ios::binary) << "this is not a png at all";
    EXPECT_FALSE(readPng(path("g.png"), back, error));
    EXPECT_NE(error.find("not a PNG"), std::string::npos) << error;

    Rgba8Image image;
    image.width = 64;
    image.height = 64;
    image.pixels.assign(64 * 64 * 4, 0);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = static_cast<uint8_t>((i * 2654435761u) >> 24); // incompressible
    }
    ASSERT_TRUE(writePng(path("full.png"), image, error)) << error;
    const std::string bytes = readBytes(path("full.png"));
    std::ofstream(path("cut.png"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    EXPECT_FALSE(readPng(path("cut.png"), back, error));
    EXPECT_NE(error.find(path("cut.png")), std::string::npos) << error;
    EXPECT_FALSE(readPng(path("missing.png"), back, error));
    EXPECT_NE(error.find("No such file"), std::string::npos) << error;
}

TEST_F(ImageIoTest, ReadPngRefusesAChunkLongerThanTheFileBeforeLibpngTakesItsRoom) {
    // A screenshot whose text chunk's length says 1.8 GB in a file of a kilobyte: libpng would
    // take (and clear) 1.8 GB before reading it.
    Rgba8Image image;
    image.width = 6;
    image.height = 4;
    image.pixels.assign(6 * 4 * 4, 200);
    std::string error;
    ASSERT_TRUE(writePng(path("shot.png"), image, error, {{"raylab-settings", "{}"}})) << error;
    std::string bytes = readBytes(path("shot.png"));
    const std::size_t text = bytes.find("tEXt");
    ASSERT_NE(text, std::string::npos);
    bytes[text - 4] = static_cast<char>(0x6c); // length 0x6c0000xx: about 1.8 GB
    std::ofstream(path("claims.png"), std::ios::binary) << bytes;
    Rgba8Image back;
    EXPECT_FALSE(readPng(path("claims.png"), back, error));
    EXPECT_NE(error.find("a tEXt chunk of"), std::string::npos) << error;
    EXPECT_NE(error.find(path("claims.png")), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST_F(ImageIoTest, PfmRoundTripIsBitExact) {
    const Framebuffer fb = testImage(5, 4);
    std::string error;
    ASSERT_TRUE(writePfm(path("a.pfm"), fb, error)) << error;
    Framebuffer back;
    ASSERT_TRUE(readPfm(path("a.pfm"), back, error)) << error;
    ASSERT_EQ(back.width, 5);
    ASSERT_EQ(back.height, 4);
    ASSERT_EQ(back.pixels.size(), fb.pixels.size());
    EXPECT_EQ(std::memcmp(back.pixels.data(), fb.pixels.data(), fb.pixels.size() * 12), 0);
}

TEST_F(ImageIoTest, PfmHeaderAndBottomToTopRows) {
    Framebuffer fb(2, 2);
    fb.at(0, 0) = glm::vec3(1.0f, 2.0f, 3.0f);  // top left
    fb.at(0, 1) = glm::vec3(-4.0f, 5.5f, 6.0f); // bottom left
    std::string error;
    ASSERT_TRUE(writePfm(path("r.pfm"), fb, error)) << error;
    const std::string bytes = readBytes(path("r.pfm"));
    const std::string header = "PF\n2 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 2 * 2 * 3 * 4);
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    // The first pixel stored is the bottom-left one, little-endian.
    const uint32_t bits = std::bit_cast<uint32_t>(-4.0f);
    const unsigned char* first =
        reinterpret_cast<const unsigned char*>(bytes.data()) + header.size();
    EXPECT_EQ(first[0], bits & 0xff);
    EXPECT_EQ(first[3], bits >> 24);
    float stored[3];
    std::memcpy(stored, first, sizeof stored);
    EXPECT_EQ(stored[1], 5.5f);
    // The third pixel stored is the top-left one.
    std::memcpy(stored, first + 2 * 12, sizeof stored);
    EXPECT_EQ(stored[0], 1.0f);
    EXPECT_EQ(stored[2], 3.0f);
}

TEST_F(ImageIoTest, PfmReadsBigEndianAndGrey) {
    // Big-endian grey ("Pf", positive scale), 1 x 2: bottom 0.5, top 2.0.
    std::string bytes = "Pf\n1 2\n1.0\n";
    for (const float v : {0.5f, 2.0f}) {
        const uint32_t b = std::bit_cast<uint32_t>(v);
        for (int shift = 24; shift >= 0; shift -= 8) {
            bytes.push_back(static_cast<char>((b >> shift) & 0xff));
        }
    }
    std::ofstream(path("be.pfm"), std::ios::binary) << bytes;
    Framebuffer back;
    std::string error;
    ASSERT_TRUE(readPfm(path("be.pfm"), back, error)) << error;
    EXPECT_EQ(back.at(0, 0), glm::vec3(2.0f));
    EXPECT_EQ(back.at(0, 1), glm::vec3(0.5f));
}

TEST_F(ImageIoTest, PfmRejectsMalformedFiles) {
    const std::string good = "PF\n1 1\n-1.0\n" + std::string(12, '\0');
    const std::vector<std::string> bad = {
        "",
        "P6\n1 1\n255\n...",
        "PF\n1 1\n-1.0\n" + std::string(11, '\0'),  // short
        "PF\n1 1\n-1.0\n" + std::string(13, '\0'),  // long
        "PF\n0 1\n-1.0\n",                          // zero size
        "PF\n99999 1\n-1.0\n",                      // huge
        "PF\n1 1\nnan\n" + std::string(12, '\0'),   // bad scale
        "PF\n1x 1\n-1.0\n" + std::string(12, '\0'), // trailing garbage in a number
    };
    std::string error;
    Framebuffer back;
    std::ofstream(path("good.pfm"), std::ios::binary) << good;
    EXPECT_TRUE(readPfm(path("good.pfm"), back, error)) << error;
    for (std::size_t i = 0; i < bad.size(); ++i) {
        const std::string p = path("bad" + std::to_string(i) + ".pfm");
        std::ofstream(p, std::ios::binary) << bad[i];
        error.clear();
        EXPECT_FALSE(readPfm(p, back, error)) << i;
        EXPECT_NE(error.find(p), std::string::npos) << error;
    }
}

TEST_F(ImageIoTest, ExrRoundTripIsExact) {
    const Framebuffer fb = testImage(6, 5);
    std::string error;
    ASSERT_TRUE(writeImage(path("a.exr"), fb, DisplayMode::Lab, 0.0f, error)) << error;
    Framebuffer back;
    ASSERT_TRUE(readExr(path("a.exr"), back, error)) << error;
    ASSERT_EQ(back.width, 6);
    ASSERT_EQ(back.height, 5);
    EXPECT_EQ(std::memcmp(back.pixels.data(), fb.pixels.data(), fb.pixels.size() * 12), 0);
    EXPECT_EQ(files(), std::vector<std::string>{"a.exr"});
    std::ofstream(path("bad.exr"), std::ios::binary) << "nope";
    EXPECT_FALSE(readExr(path("bad.exr"), back, error));
    EXPECT_NE(error.find(path("bad.exr")), std::string::npos) << error;
}

TEST_F(ImageIoTest, FailedWritesNameThePathAndLeaveNothing) {
    const Framebuffer fb = testImage(3, 3);
    for (const std::string& target :
         {path("no-such-dir/a.png"), path("no-such-dir/a.pfm"), path("no-such-dir/a.exr"),
          std::string("/proc/raylab-test.png"), std::string("/proc/raylab-test.exr")}) {
        std::string error;
        EXPECT_FALSE(writeImage(target, fb, DisplayMode::Lab, 0.0f, error)) << target;
        EXPECT_NE(error.find("'" + target + "'"), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        EXPECT_FALSE(fs::exists(target));
    }
    // A folder in the way.
    fs::create_directory(path("taken.png"));
    std::string error;
    EXPECT_FALSE(writeImage(path("taken.png"), fb, DisplayMode::Lab, 0.0f, error));
    EXPECT_NE(error.find("Is a directory"), std::string::npos) << error;
    EXPECT_EQ(files(), std::vector<std::string>{"taken.png"});
}

TEST_F(ImageIoTest, UnsupportedExtensionIsAClearError) {
    const Framebuffer fb = testImage(2, 2);
    std::string error;
    EXPECT_FALSE(writeImage(path("a.jpg"), fb, DisplayMode::Lab, 0.0f, error));
    EXPECT_NE(error.find(".jpg"), std::string::npos) << error;
    EXPECT_TRUE(files().empty());
    EXPECT_TRUE(isSupportedImagePath("x/y.PNG"));
    EXPECT_TRUE(isSupportedImagePath("y.pfm"));
    EXPECT_TRUE(isSupportedImagePath("y.Exr"));
    EXPECT_FALSE(isSupportedImagePath("y.png.txt"));
    EXPECT_FALSE(isSupportedImagePath("png"));
}

TEST_F(ImageIoTest, OverwritesAnExistingFileWhole) {
    std::string error;
    ASSERT_TRUE(writePfm(path("o.pfm"), testImage(8, 8), error)) << error;
    ASSERT_TRUE(writePfm(path("o.pfm"), testImage(2, 2), error)) << error;
    Framebuffer back;
    ASSERT_TRUE(readPfm(path("o.pfm"), back, error)) << error;
    EXPECT_EQ(back.width, 2);
    EXPECT_EQ(files(), std::vector<std::string>{"o.pfm"});
}

} // namespace
} // namespace raylab
