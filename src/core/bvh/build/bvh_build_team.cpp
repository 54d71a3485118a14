#include "bvh/build/bvh_build_team.h"

#include <chrono>
#include <immintrin.h>

namespace raylab {

namespace {

// How long a thread between loops spins before it sleeps: the build's top runs loops back to
// back with a few microseconds of one thread's work between them, and a sleeping thread takes
// tens of microseconds to wake (PERFORMANCE.md, "What each change gained: the BVH build").
constexpr auto kSpin = std::chrono::microseconds(100);

} // namespace

template <typename Done> void BuildTeam::spinUntil(const Done& done) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (;;) {
        for (int i = 0; i < 64; ++i) {
            if (done()) {
                return;
            }
            _mm_pause();
        }
        if (std::chrono::steady_clock::now() > until) {
            return;
        }
    }
}

BuildTeam::BuildTeam(int threads) {
    for (int i = 1; i < threads; ++i) {
        helpers_.emplace_back([this] { helperLoop(); });
    }
}

BuildTeam::~BuildTeam() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : helpers_) {
        t.join();
    }
}

void BuildTeam::forEach(std::size_t count, const std::function<void(std::size_t)>& job) {
    if (count == 0) {
        return;
    }
    if (helpers_.empty() || count == 1) {
        for (std::size_t i = 0; i < count; ++i) {
            job(i);
        }
        return;
    }
    {
        const std::lock_guard lock(mutex_);
        job_ = &job;
        count_ = count;
        next_ = 0;
        done_ = 0;
        ++generation_;
    }
    wake_.notify_all();
    work();
    spinUntil([this, count] { return done_.load(std::memory_order_acquire) == count; });
    std::unique_lock lock(mutex_);
    finished_.wait(lock, [this] { return done_ == count_; });
    job_ = nullptr;
}

void BuildTeam::work() {
    std::unique_lock lock(mutex_);
    while (job_ && next_ < count_) {
        const std::size_t i = next_++;
        const auto* job = job_;
        lock.unlock();
        (*job)(i);
        lock.lock();
        if (++done_ == count_) {
            finished_.notify_one();
        }
    }
}

void BuildTeam::helperLoop() {
    unsigned long seen = 0;
    for (;;) {
        spinUntil([&] {
            return stop_.load(std::memory_order_acquire) ||
                   generation_.load(std::memory_order_acquire) != seen;
        });
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) {
                return;
            }
            seen = generation_;
        }
        work();
    }
}

} // namespace raylab
