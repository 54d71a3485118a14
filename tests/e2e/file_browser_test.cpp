// The panel's file browser: a folder's subfolders and mesh files in order, hidden and other
// files left out, walking into folders and up, picking a file, a folder that cannot be listed,
// and where browsing starts.

#include "file_browser.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace raylab {
namespace {

namespace fs = std::filesystem;

class FileBrowserTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("raylab-browser-" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_ / "meshes" / "deeper");
        fs::create_directories(root_ / "Bunnies");
        fs::create_directories(root_ / ".hidden");
        for (const char* name : {"z.ply", "a.OBJ", "B.glb", "notes.txt", ".secret.obj"}) {
            std::ofstream(root_ / name) << "12345";
        }
        std::ofstream(root_ / "meshes" / "dragon.ply") << "ply";
        fs::create_directory_symlink(root_ / "meshes", root_ / "link-to-meshes");
        fs::create_symlink(root_ / "missing.obj", root_ / "broken.obj");
    }
    void TearDown() override { fs::remove_all(root_); }

    static std::vector<std::string> names(const FileBrowser& b) {
        std::vector<std::string> out;
        for (const BrowserEntry& e : b.entries()) {
            out.push_back(e.name);
        }
        return out;
    }
    fs::path root_;
};

TEST_F(FileBrowserTest, FoldersThenMeshFilesEachByNameIgnoringCase) {
    FileBrowser b;
    ASSERT_TRUE(b.open(root_ / ".." / root_.filename() / "")) << b.error();
    EXPECT_EQ(b.folder(), root_);
    EXPECT_EQ(names(b), (std::vector<std::string>{"..", "Bunnies", "link-to-meshes", "meshes",
                                                  "a.OBJ", "B.glb", "z.ply"}));
    EXPECT_TRUE(b.entries()[1].folder);
    EXPECT_FALSE(b.entries()[4].folder);
    EXPECT_EQ(b.entries()[6].bytes, 5u);
    EXPECT_EQ(b.leftOut(), 0u);
    EXPECT_TRUE(b.error().empty());
}

TEST_F(FileBrowserTest, ChoosingWalksIntoFoldersAndUpAndPicksAFile) {
    FileBrowser b;
    ASSERT_TRUE(b.open(root_));
    std::string chosen;
    EXPECT_FALSE(b.choose(3, chosen)); // "meshes"
    EXPECT_EQ(b.folder(), root_ / "meshes");
    EXPECT_EQ(names(b), (std::vector<std::string>{"..", "deeper", "dragon.ply"}));
    EXPECT_TRUE(b.choose(2, chosen));
    EXPECT_EQ(chosen, (root_ / "meshes" / "dragon.ply").string());
    EXPECT_FALSE(b.choose(0, chosen)); // ".."
    EXPECT_EQ(b.folder(), root_);
    EXPECT_FALSE(b.choose(99, chosen)); // out of range: nothing happens
    EXPECT_EQ(b.folder(), root_);
}

TEST_F(FileBrowserTest, AFolderThatCannotBeListedKeepsThePreviousListing) {
    FileBrowser b;
    ASSERT_TRUE(b.open(root_));
    const std::vector<std::string> before = names(b);
    EXPECT_FALSE(b.open(root_ / "no-such-folder"));
    EXPECT_NE(b.error().find("cannot list"), std::string::npos) << b.error();
    EXPECT_NE(b.error().find("no-such-folder"), std::string::npos);
    EXPECT_EQ(b.error().find('\n'), std::string::npos);
    EXPECT_EQ(names(b), before);
    EXPECT_EQ(b.folder(), root_);
    EXPECT_FALSE(b.open(root_ / "z.ply")); // a file is not a folder
    EXPECT_TRUE(b.open(root_));
    EXPECT_TRUE(b.error().empty());
}

TEST_F(FileBrowserTest, TheRootHasNoParentEntry) {
    FileBrowser b;
    ASSERT_TRUE(b.open("/"));
    ASSERT_FALSE(b.entries().empty());
    EXPECT_NE(b.entries()[0].name, "..");
}

TEST_F(FileBrowserTest, AHugeFolderSaysHowManyWereLeftOut) {
    const fs::path big = root_ / "big";
    fs::create_directory(big);
    for (std::size_t i = 0; i < FileBrowser::kMaxEntries + 7; ++i) {
        std::string name = std::to_string(i); // (not "m" + ...: GCC 12's -Wrestrict misfires)
        name += ".obj";
        std::ofstream(big / name);
    }
    FileBrowser b;
    ASSERT_TRUE(b.open(big));
    EXPECT_EQ(b.entries().size(), FileBrowser::kMaxEntries + 1); // and ".."
    EXPECT_EQ(b.leftOut(), 7u);
}

TEST_F(FileBrowserTest, BrowsingStartsWhereThePathFieldPoints) {
    EXPECT_EQ(FileBrowser::startFolder((root_ / "meshes" / "dragon.ply").string()),
              root_ / "meshes");
    EXPECT_EQ(FileBrowser::startFolder((root_ / "meshes").string()), root_ / "meshes");
    EXPECT_EQ(FileBrowser::startFolder("cornell"), fs::current_path());
    EXPECT_EQ(FileBrowser::startFolder(""), fs::current_path());
    EXPECT_EQ(FileBrowser::startFolder((root_ / "gone" / "x.obj").string()), fs::current_path());
}

} // namespace
} // namespace raylab
