#pragma once
// The threads of one BVH build (internal to core): started once per build, they run the build's
// parallel loops, so a loop costs a wake-up rather than a thread start. Nothing the loops
// compute may depend on which thread ran which index: that is how the build stays the same
// whatever the thread count.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace raylab {

class BuildTeam {
public:
    // `threads` threads in all, the caller of forEach included (at least 1).
    explicit BuildTeam(int threads);
    ~BuildTeam(); // stops and joins the helpers
    BuildTeam(const BuildTeam&) = delete;
    BuildTeam& operator=(const BuildTeam&) = delete;

    int size() const { return static_cast<int>(helpers_.size()) + 1; }
    // Loops run on more than one thread since the team started.
    unsigned long loopsShared() const { return generation_.load(std::memory_order_relaxed); }

    // Runs job(i) once for every i in [0, count), indices handed out in increasing order to
    // whichever thread asks first; returns when all are done. Not reentrant: a job must not call
    // forEach.
    void forEach(std::size_t count, const std::function<void(std::size_t)>& job);

private:
    void helperLoop();
    void work(); // takes indices of the current loop until none is left
    // Spins for a short while (kSpin, bvh_build_team.cpp) or until done() holds; the caller then
    // waits on its condition variable, which returns at once if done() holds.
    template <typename Done> static void spinUntil(const Done& done);

    std::mutex mutex_;
    std::condition_variable wake_;     // a new loop, or stop
    std::condition_variable finished_; // the last index of the loop is done
    const std::function<void(std::size_t)>* job_ = nullptr;
    std::size_t count_ = 0;
    std::size_t next_ = 0; // next index to hand out
    // Written under mutex_; atomic so that a waiting thread may spin on them without it.
    std::atomic<std::size_t> done_ = 0; // indices finished
    std::atomic<unsigned long> generation_ = 0;
    std::atomic<bool> stop_ = false;
    std::vector<std::thread> helpers_;
};

} // namespace raylab
