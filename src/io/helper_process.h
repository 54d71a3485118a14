#pragma once
// Runs a helper executable and collects what it writes on its descriptor 3, under a wall-clock
// limit and a cancel check. The helper gets /dev/null as its standard input, output and error (so
// nothing it prints reaches the user's terminal), the pipe as descriptor 3, and no other
// descriptor of the parent.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace raylab {

struct HelperRun {
    bool started = false;      // false: spawning failed, see `error`
    std::string error;         // why it could not start
    std::vector<uint8_t> data; // everything read from descriptor 3 (at most the cap)
    bool timedOut = false;     // killed by us: the time limit passed
    bool cancelled = false;    // killed by us: cancelled() said so
    bool overCap = false;      // killed by us: it wrote more than the cap
    int exitCode = -1;         // when it exited
    int signal = 0;            // when a signal ended it (SIGKILL also for the three above)
};

struct HelperOptions {
    double seconds = 60.0; // wall clock before the helper is killed
    // "NAME=VALUE" entries for the helper's environment, on top of the parent's (an entry
    // replaces the parent's variable of the same name).
    std::vector<std::string> environment;
    std::size_t maxBytes = 0; // more than this on descriptor 3 kills the helper
    // Given what has arrived, the total the helper will send when its header says so, else 0;
    // the buffer then takes that room at once (at most maxBytes). May be empty.
    std::function<std::size_t(const uint8_t* data, std::size_t size)> expectedBytes;
    std::function<bool()> cancelled;             // polled about every 20 ms; may be empty
    std::function<void(double seconds)> running; // likewise; the time since the spawn
    // Called once with everything the helper sent, as soon as it has closed its end and before
    // the wait for its exit, so that the caller's work on the data overlaps the helper's ending.
    // Not called when the helper was killed while writing (over the cap, the time limit,
    // cancelled); it may still be killed or crash afterwards, so what the data means is decided
    // only from the HelperRun that runHelper returns. May be empty.
    std::function<void(const std::vector<uint8_t>& data)> received;
};

// Spawns `argv[0]` with `argv` (posix_spawn; the parent's environment with
// options.environment on top) and waits for it.
// Never leaves a child behind: whatever happens, the helper has been waited for on return.
HelperRun runHelper(const std::vector<std::string>& argv, const HelperOptions& options);

} // namespace raylab
