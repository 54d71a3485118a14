// Partial render files (io/partial_file.h): what is written reads back exactly, and files that are
// not partial renders, or lie about their size, are refused in one line before anything large is
// allocated.

#include "io/partial_file.h"
#include "temp_dir_test.h"

#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>
#include <random>

namespace raylab {
namespace {

class PartialFile : public test::TempDirTest {};

TEST_F(PartialFile, WhatIsWrittenReadsBackExactly) {
    PartialRender partial;
    partial.imageWidth = 40;
    partial.imageHeight = 30;
    partial.window = FilmWindow{5, 7, 26, 19};
    partial.firstSample = 3;
    partial.endSample = 11;
    partial.settingsJson = "{\"image\": {\"width\": 40, \"height\": 30}}";
    partial.scene = "cornell";
    partial.sceneHash = "lab box";
    const std::size_t pixels = 21 * 12;
    std::mt19937 random(5);
    std::uniform_real_distribution<float> value(-3.0f, 1000.0f);
    for (std::size_t i = 0; i < pixels; ++i) {
        PixelSum sum;
        for (int s = 0; s < 8; ++s) {
            sum.add(glm::vec3(value(random), value(random) * 1e-9f, value(random) * 1e6f));
        }
        partial.sums.push_back(sum);
        partial.squares.emplace_back(value(random), value(random), value(random));
    }
    std::string error;
    ASSERT_TRUE(writePartial(path("p.exr"), partial, error)) << error;
    PartialRender back;
    ASSERT_TRUE(readPartial(path("p.exr"), back, error)) << error;
    EXPECT_EQ(back.imageWidth, 40);
    EXPECT_EQ(back.imageHeight, 30);
    EXPECT_EQ(back.window, partial.window);
    EXPECT_EQ(back.firstSample, 3u);
    EXPECT_EQ(back.endSample, 11u);
    EXPECT_EQ(back.settingsJson, partial.settingsJson);
    EXPECT_EQ(back.scene, "cornell");
    EXPECT_EQ(back.sceneHash, "lab box");
    EXPECT_TRUE(back.sums == partial.sums);
    EXPECT_TRUE(back.squares == partial.squares);
    EXPECT_EQ(files(), std::vector<std::string>{"p.exr"});
}

TEST_F(PartialFile, AHeaderClaimingAHugePictureIsRefusedBeforeItsPixelsAreRead) {
    // A 16384 x 16384 partial with no pixels written: reading it would take tens of GiB.
    {
        const Imath::Box2i window(Imath::V2i(0, 0), Imath::V2i(16383, 16383));
        Imf::Header header(window, window);
        for (const char* c : {"R", "G", "B"}) {
            header.channels().insert(c, Imf::Channel(Imf::FLOAT));
            for (int k = 0; k < 4; ++k) {
                header.channels().insert(std::string("raylab.") + c + "." + std::to_string(k),
                                         Imf::Channel(Imf::UINT));
            }
        }
        header.insert("raylab.partial", Imf::IntAttribute(1));
        header.insert("raylab.firstSample", Imf::IntAttribute(0));
        header.insert("raylab.endSample", Imf::IntAttribute(1));
        header.insert("raylab.settings", Imf::StringAttribute("{}"));
        header.insert("raylab.scene", Imf::StringAttribute("cornell"));
        header.insert("raylab.sceneHash", Imf::StringAttribute("lab box"));
        Imf::OutputFile file(path("huge.exr").c_str(), header);
    }
    PartialRender back;
    std::string error;
    EXPECT_FALSE(readPartial(path("huge.exr"), back, error));
    EXPECT_NE(error.find("needs"), std::string::npos) << error;
    EXPECT_NE(error.find("GiB"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST_F(PartialFile, AnAttributeLargerThanTheFileIsRefusedBeforeOpenExrReadsIt) {
    // OpenEXR would take the 2 GiB this attribute claims before finding the file too short.
    const std::string forged =
        std::string(RAYLAB_SOURCE_DIR) + "/tests/fuzz/corpus/partial_file/huge_attribute";
    PartialRender back;
    std::string error;
    EXPECT_FALSE(readPartial(forged, back, error));
    EXPECT_NE(error.find("an attribute of 2147483632 bytes"), std::string::npos) << error;
}

TEST_F(PartialFile, OtherFilesAreRefusedByName) {
    PartialRender back;
    std::string error;
    EXPECT_FALSE(readPartial(path("missing.exr"), back, error));
    EXPECT_NE(error.find("missing.exr"), std::string::npos) << error;
    {
        const Imath::Box2i window(Imath::V2i(0, 0), Imath::V2i(3, 3));
        Imf::Header header(window, window);
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path("plain.exr").c_str(), header);
    }
    EXPECT_FALSE(readPartial(path("plain.exr"), back, error));
    EXPECT_NE(error.find("not a raylab partial render"), std::string::npos) << error;
}

} // namespace
} // namespace raylab
