// raylab-bench's look at the system (bench_system.h): which of the kernel's DAMON threads run,
// read from a proc file system laid out in a temporary directory. (bench_cli_test checks that the
// bench reports what the real /proc holds.)

#include "bench/bench_system.h"
#include "temp_dir_test.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace raylab::bench {
namespace {

namespace fs = std::filesystem;

// A fresh folder standing for /proc (temp_dir_test.h).
class BenchSystem : public test::TempDirTest {
protected:
    // Process `entry` (a directory name) whose comm file holds `name` and a newline.
    void process(const std::string& entry, const std::string& name) const {
        fs::create_directories(dir_ / entry);
        std::ofstream(dir_ / entry / "comm") << name << "\n";
    }
};

TEST_F(BenchSystem, FindsTheDamonThreadsInNameOrder) {
    process("1", "systemd");
    process("311", "kdamond.1");
    process("77", "kdamond.0");
    process("4242", "raylab-bench");
    EXPECT_EQ(memoryAccessMonitors(dir_.string()),
              (std::vector<std::string>{"kdamond.0", "kdamond.1"}));
}

TEST_F(BenchSystem, IgnoresWhatIsNotAProcessOrHasNoName) {
    process("self", "kdamond.0");         // not a process id
    process("12a", "kdamond.2");          // nor this
    fs::create_directories(dir_ / "900"); // a process that ended: no comm file
    process("901", "kworker/0:1");
    process("902", "my-kdamond"); // the name must begin with kdamond
    std::ofstream(dir_ / "903") << "a file, not a directory\n";
    EXPECT_TRUE(memoryAccessMonitors(dir_.string()).empty());
}

TEST_F(BenchSystem, NoSuchDirectoryMeansNone) {
    EXPECT_TRUE(memoryAccessMonitors((dir_ / "absent").string()).empty());
}

} // namespace
} // namespace raylab::bench
