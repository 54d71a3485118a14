#include "redraw_schedule.h"

#include <algorithm>

namespace raylab::viewer {

RedrawSchedule::RedrawSchedule(double framesPerSecond, bool continuous)
    : period_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(1.0 / framesPerSecond))),
      continuous_(continuous) {}

void RedrawSchedule::want(TimePoint now, int frames) {
    if (framesWanted_ == 0) {
        wantedSince_ = now;
    }
    framesWanted_ = std::max(framesWanted_, std::max(frames, 1));
}

void RedrawSchedule::wantAt(TimePoint when) { wantedAt_ = std::min(wantedAt_, when); }

void RedrawSchedule::resume(TimePoint now) {
    want(now);
    wantedSince_ = now;
    wantedAt_ = std::max(wantedAt_, now);
    if (shownOnce_) {
        lastShown_ = now;
    }
}

bool RedrawSchedule::due(TimePoint now) const {
    const bool wanted = continuous_ || framesWanted_ > 0 || now >= wantedAt_;
    return wanted && now >= nextSlot_;
}

RedrawSchedule::TimePoint RedrawSchedule::wakeAt() const {
    if (continuous_ || framesWanted_ > 0) {
        return nextSlot_;
    }
    return wantedAt_ == TimePoint::max() ? wantedAt_ : std::max(wantedAt_, nextSlot_);
}

void RedrawSchedule::frameStarted(TimePoint now) {
    // The frame answers the oldest want it serves.
    TimePoint since = now;
    if (framesWanted_ > 0) {
        since = std::min(since, wantedSince_);
        --framesWanted_;
    }
    if (now >= wantedAt_) {
        since = std::min(since, wantedAt_);
        wantedAt_ = TimePoint::max();
    }
    if (continuous_ && shownOnce_) {
        since = lastShown_;
    }
    startedWantedSince_ = shownOnce_ ? std::max(since, lastShown_) : since;
    // Slots keep their grid while frames keep up (a frame late by less than a period may be
    // followed sooner); after a longer gap (idle) the grid restarts at this frame.
    nextSlot_ = now > nextSlot_ + period_ ? now + period_ : nextSlot_ + period_;
}

double RedrawSchedule::frameShown(TimePoint now) {
    const bool first = !shownOnce_;
    shownOnce_ = true;
    lastShown_ = now;
    if (framesWanted_ > 0) {
        wantedSince_ = now; // the frames still wanted are wanted from this swap on
    }
    return first ? -1.0 : std::chrono::duration<double>(now - startedWantedSince_).count();
}

} // namespace raylab::viewer
