#pragma once
// A copy of a live value that changes at most once per period: what the panel shows of values
// that change with every frame (navigation, timings), so that an untouched panel draws the same
// pixels from frame to frame and its cached pixels are reused (panel_layer.h).
//
// The copy follows the live value on the first call, whenever the caller forces it, and else
// only once a period has passed since the copy last changed. catchUpAt compares Key(copy) with
// Key(live) (Key: a projection, e.g. a pointer to a member; the whole value by default) and says
// when the copy will follow, so that the caller can ask for a frame then.
//
// Times are steady_clock time points given by the caller: no clock is read here.

#include <chrono>
#include <functional>
#include <optional>

namespace raylab::viewer {

// T: copyable and equality-comparable; std::invoke(Key, const T&) equality-comparable.
template <typename T, auto Key = std::identity{}> class ThrottledCopy {
public:
    using Clock = std::chrono::steady_clock;
    using TimePoint = Clock::time_point;

    // period > 0.
    explicit ThrottledCopy(Clock::duration period) : period_(period) {}

    // Copies `live` into shown() on the first call, when `force`, or when at least one period has
    // passed since shown() last changed. Returns whether it copied.
    bool follow(const T& live, TimePoint now, bool force = false) {
        if (copied_ && !force && now - changedAt_ < period_) {
            return false;
        }
        if (!copied_ || !(shown_ == live)) {
            shown_ = live;
            changedAt_ = now;
        }
        copied_ = true;
        return true;
    }

    // The copy (T{} before the first follow).
    const T& shown() const { return shown_; }

    // nullopt when Key(shown()) equals Key(live); else the earliest time at which follow() will
    // copy `live` unforced (a time point in the past before the first follow).
    std::optional<TimePoint> catchUpAt(const T& live) const {
        if (copied_ && std::invoke(Key, shown_) == std::invoke(Key, live)) {
            return std::nullopt;
        }
        return copied_ ? changedAt_ + period_ : TimePoint{};
    }

private:
    Clock::duration period_;
    T shown_{};
    TimePoint changedAt_{}; // when shown_ last changed
    bool copied_ = false;
};

} // namespace raylab::viewer
