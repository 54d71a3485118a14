// The viewer's background scene loads (scene_loader.h) through the real raylab-import: a result
// once, a new load replacing a running one, cancel killing the helper at once, and a loader that
// is destroyed during a load returning without waiting for it. The hanging helper comes from its
// test hook RAYLAB_IMPORT_TEST_CRASH (src/import/test_hooks.h).

#include "scene_loader.h"
#include "temp_dir_test.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <thread>

namespace raylab::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Sets the helper's test hook for the life of the object.
struct HelperHook {
    explicit HelperHook(const char* what) { ::setenv("RAYLAB_IMPORT_TEST_CRASH", what, 1); }
    ~HelperHook() { ::unsetenv("RAYLAB_IMPORT_TEST_CRASH"); }
    HelperHook(const HelperHook&) = delete;
    HelperHook& operator=(const HelperHook&) = delete;
};

class SceneLoads : public test::TempDirTest {
protected:
    std::string triangle(const std::string& name) const {
        std::ofstream(path(name)) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        return path(name);
    }
    // Polls until a result comes or `seconds` pass.
    static std::optional<SceneLoadResult> waitResult(SceneLoader& loader, double seconds) {
        const auto start = Clock::now();
        while (secondsSince(start) < seconds) {
            if (auto result = loader.poll()) {
                return result;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return std::nullopt;
    }
    // Waits until the running load has run `seconds` (its helper is started by then).
    static void waitRunning(const SceneLoader& loader, double seconds) {
        const auto start = Clock::now();
        while (secondsSince(start) < 10.0) {
            const auto progress = loader.progress();
            ASSERT_TRUE(progress.has_value());
            if (progress->seconds >= seconds) {
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        FAIL() << "the load's clock did not reach " << seconds << " s";
    }
};

TEST_F(SceneLoads, AMeshLoadsAndItsResultComesOnce) {
    const std::string obj = triangle("t.obj");
    int done = 0;
    SceneLoader loader(ImportLimits{}, [&done] { ++done; });
    loader.start(obj);
    const auto progress = loader.progress();
    ASSERT_TRUE(progress.has_value());
    EXPECT_EQ(progress->source, obj);
    const auto result = waitResult(loader, 20.0);
    ASSERT_TRUE(result.has_value());
    ASSERT_TRUE(result->scene) << result->error;
    EXPECT_EQ(result->scene->source, obj);
    EXPECT_EQ(result->scene->scene.triangles.size(), 1u);
    EXPECT_EQ(done, 1);
    EXPECT_FALSE(loader.busy());
    EXPECT_FALSE(loader.progress().has_value());
    EXPECT_FALSE(loader.poll().has_value());
}

TEST_F(SceneLoads, ANewLoadReplacesARunningOne) {
    const std::string hanging = triangle("hang.obj");
    const std::string obj = triangle("t.obj");
    SceneLoader loader(ImportLimits{});
    {
        const HelperHook hook("hang");
        loader.start(hanging);
        waitRunning(loader, 0.3);
    }
    loader.start(obj);
    EXPECT_EQ(loader.progress()->source, obj);
    const auto result = waitResult(loader, 20.0);
    ASSERT_TRUE(result.has_value());
    ASSERT_TRUE(result->scene) << result->error;
    EXPECT_EQ(result->scene->source, obj);
    EXPECT_FALSE(waitResult(loader, 0.3).has_value()); // the replaced load gives nothing
}

TEST_F(SceneLoads, CancelStopsAHangingLoadAtOnceAndGivesNothing) {
    const std::string obj = triangle("t.obj");
    SceneLoader loader(ImportLimits{});
    const HelperHook hook("hang");
    loader.start(obj);
    waitRunning(loader, 0.3);
    EXPECT_TRUE(loader.cancel());
    EXPECT_FALSE(loader.busy());
    EXPECT_FALSE(loader.cancel()); // nothing left to cancel
    EXPECT_FALSE(waitResult(loader, 0.3).has_value());
}

TEST_F(SceneLoads, DestroyingTheLoaderDoesNotWaitForTheLoad) {
    const std::string obj = triangle("t.obj");
    const HelperHook hook("hang");
    auto loader = std::make_unique<SceneLoader>(ImportLimits{});
    loader->start(obj);
    waitRunning(*loader, 0.3);
    const auto start = Clock::now();
    loader.reset();
    EXPECT_LT(secondsSince(start), SceneLoader::kCloseGraceSeconds + 0.2);
}

TEST_F(SceneLoads, TheLimitsReachTheHelper) {
    const std::string obj = triangle("t.obj");
    const HelperHook hook("hang");
    ImportLimits limits;
    limits.seconds = 0.3;
    SceneLoader loader(limits);
    loader.start(obj);
    const auto result = waitResult(loader, 20.0);
    ASSERT_TRUE(result.has_value());
    EXPECT_FALSE(result->scene);
    EXPECT_EQ(result->error, "cannot load mesh '" + obj +
                                 "': took longer than 0.3 s (the importer "
                                 "was stopped)");
}

} // namespace
} // namespace raylab::viewer
