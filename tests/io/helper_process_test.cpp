// runHelper with /bin/sh as the helper: what it writes on descriptor 3 arrives whole, the
// environment given on top of the parent's reaches it, the data is handed over before the wait
// for the helper's exit, and its exit code, its signal and the time limit are reported.

#include "io/helper_process.h"

#include <chrono>
#include <cstdlib>
#include <gtest/gtest.h>
#include <string>

namespace raylab {
namespace {

std::string text(const std::vector<uint8_t>& bytes) { return {bytes.begin(), bytes.end()}; }

// The options' cap is 0 by default (any byte is too many); these tests allow 64 MiB.
HelperRun shell(const std::string& script, HelperOptions options = {}) {
    options.maxBytes = std::size_t{64} << 20;
    return runHelper({"/bin/sh", "-c", script}, options);
}

TEST(HelperProcess, WhatTheHelperWritesOnDescriptorThreeArrivesWhole) {
    const HelperRun run = shell("head -c 3000000 /dev/zero | tr '\\0' x >&3; printf end >&3");
    ASSERT_TRUE(run.started) << run.error;
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.signal, 0);
    ASSERT_EQ(run.data.size(), 3000003u);
    EXPECT_EQ(text(run.data).substr(2999998), "xxend");
}

TEST(HelperProcess, TheGivenEnvironmentGoesOnTopOfTheParents) {
    ::setenv("RAYLAB_HELPER_TEST_KEPT", "parent", 1);
    ::setenv("RAYLAB_HELPER_TEST_REPLACED", "parent", 1);
    HelperOptions options;
    options.environment = {"RAYLAB_HELPER_TEST_REPLACED=helper", "RAYLAB_HELPER_TEST_NEW=new"};
    const HelperRun run = shell("printf '%s %s %s' \"$RAYLAB_HELPER_TEST_KEPT\" "
                                "\"$RAYLAB_HELPER_TEST_REPLACED\" \"$RAYLAB_HELPER_TEST_NEW\" >&3",
                                options);
    EXPECT_EQ(text(run.data), "parent helper new");
    EXPECT_STREQ(std::getenv("RAYLAB_HELPER_TEST_REPLACED"), "parent"); // the parent's is kept
}

TEST(HelperProcess, TheDataIsHandedOverWhenThePipeClosesBeforeTheHelperEnds) {
    // The helper closes its end, then lingers 0.5 s: `received` must come before that.
    HelperOptions options;
    std::string seen;
    std::chrono::steady_clock::time_point receivedAt;
    options.received = [&](const std::vector<uint8_t>& data) {
        seen = text(data);
        receivedAt = std::chrono::steady_clock::now();
    };
    const auto start = std::chrono::steady_clock::now();
    const HelperRun run = shell("printf stream >&3; exec 3>&-; sleep 0.5; exit 7", options);
    const auto end = std::chrono::steady_clock::now();
    EXPECT_EQ(seen, "stream");
    EXPECT_EQ(run.exitCode, 7);
    EXPECT_LT(receivedAt - start, std::chrono::milliseconds(400));
    EXPECT_GE(end - start, std::chrono::milliseconds(500));
}

TEST(HelperProcess, ASignalEndsTheRunAndIsReported) {
    HelperOptions options;
    bool received = false;
    options.received = [&](const std::vector<uint8_t>&) { received = true; };
    const HelperRun run = shell("printf partial >&3; kill -SEGV $$", options);
    EXPECT_EQ(run.signal, SIGSEGV);
    EXPECT_EQ(text(run.data), "partial");
    EXPECT_TRUE(received); // the pipe closed by itself; the caller decides from the signal
}

TEST(HelperProcess, AHelperOverTheCapIsKilled) {
    HelperOptions options;
    options.maxBytes = 1000;
    // It writes until stopped, so it is still there to be killed.
    const HelperRun run = runHelper({"/bin/sh", "-c", "exec cat /dev/zero >&3"}, options);
    EXPECT_TRUE(run.overCap);
    EXPECT_EQ(run.signal, SIGKILL);
}

TEST(HelperProcess, AHelperPastItsTimeIsKilledAndNothingIsHandedOver) {
    HelperOptions options;
    options.seconds = 0.3;
    bool received = false;
    options.received = [&](const std::vector<uint8_t>&) { received = true; };
    const auto start = std::chrono::steady_clock::now();
    const HelperRun run = shell("exec sleep 30", options); // keeps descriptor 3 open
    EXPECT_TRUE(run.timedOut);
    EXPECT_EQ(run.signal, SIGKILL);
    EXPECT_FALSE(received);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

TEST(HelperProcess, AHelperThatClosesItsEndAndLingersIsStillHeldToItsTime) {
    HelperOptions options;
    options.seconds = 0.3;
    const HelperRun run = shell("exec 3>&-; exec sleep 30", options);
    EXPECT_TRUE(run.timedOut);
    EXPECT_EQ(run.signal, SIGKILL);
}

} // namespace
} // namespace raylab
