#include "render_worker.h"

#include "pass_size.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

#ifdef __linux__
#include <sys/resource.h>
#include <unistd.h>
#endif

#include "core/render/display_transform.h"
#include "core/render/film.h"
#include "core/render/renderer.h"
#include "difference_view.h"
#include "parked_film.h"
#include "split_view.h"

namespace raylab::viewer {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::size_t pixelCount(const RenderSettings& s) {
    return static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height);
}

// The resolution divisor of a preview for a pass expected to take `expectedSeconds`: 1 (no
// preview) when it fits the budget, else k in [2, 16] so that the preview (k*k times fewer
// pixels) about fits.
int previewDivisor(double expectedSeconds, double budgetSeconds) {
    if (!(expectedSeconds > budgetSeconds)) {
        return 1;
    }
    const double k = std::ceil(std::sqrt(expectedSeconds / budgetSeconds));
    return static_cast<int>(std::clamp(k, 2.0, 16.0));
}

// Writes the w x h image that shows `small` (sw x sh, 4 bytes a pixel) enlarged by pixel
// replication: pixel (x, y) shows small's (x * sw / w, y * sh / h).
void enlarge(const std::vector<uint8_t>& small, int sw, int sh, int w, int h, Rgba8Image& out) {
    out.width = w;
    out.height = h;
    out.pixels.resize(4 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y) {
        const std::size_t sy = static_cast<std::size_t>(y) * static_cast<std::size_t>(sh) /
                               static_cast<std::size_t>(h);
        for (int x = 0; x < w; ++x) {
            const std::size_t sx = static_cast<std::size_t>(x) * static_cast<std::size_t>(sw) /
                                   static_cast<std::size_t>(w);
            const std::size_t from = 4 * (sy * static_cast<std::size_t>(sw) + sx);
            const std::size_t to = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                                        static_cast<std::size_t>(x));
            std::copy_n(small.begin() + static_cast<std::ptrdiff_t>(from), 4,
                        out.pixels.begin() + static_cast<std::ptrdiff_t>(to));
        }
    }
}

// Linux: makes this thread "nicer" than the UI thread. The pass's helper threads are started by
// this thread and inherit it, so when tracer and UI compete for the cores (always, since a pass
// uses every core) the UI thread wins and the window keeps redrawing. Elsewhere: nothing.
void lowerThisThreadsPriority() {
#ifdef __linux__
    constexpr int kRenderNice = 10;
    setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kRenderNice);
#endif
}

double raysPerSecond(const RayCounts& counts, double seconds) {
    return seconds > 0.0 ? static_cast<double>(counts.total()) / seconds : 0.0;
}

} // namespace

bool samePicture(const RenderJob& a, const RenderJob& b) {
    return a.scene == b.scene && sameSamples(a.settings, b.settings) &&
           a.compare.has_value() == b.compare.has_value() &&
           (!a.compare || sameSamples(*a.compare, *b.compare));
}

bool sameJob(const RenderJob& a, const RenderJob& b) {
    return a.scene == b.scene && a.settings == b.settings && a.compare == b.compare &&
           a.divider == b.divider &&
           (!a.compare ||
            (a.compareMode == b.compareMode &&
             (a.compareMode != CompareMode::Difference || a.differenceScale == b.differenceScale)));
}

const RenderSettings& sideSettings(const RenderJob& job, int side) {
    return side == 1 && job.compare ? *job.compare : job.settings;
}

RenderWorker::RenderWorker(double previewBudgetSeconds, std::function<void()> onPicture)
    : previewBudgetSeconds_(previewBudgetSeconds), onPicture_(std::move(onPicture)),
      thread_([this] { run(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
        cancel_.store(true);
    }
    wake_.notify_all();
    thread_.join();
}

uint64_t RenderWorker::submit(const RenderJob& job) {
    uint64_t serial = 0;
    {
        std::lock_guard lock(mutex_);
        if (!samePicture(job, job_) && !inPreview_ && !inShortFirstPass_) {
            cancel_.store(true);
        }
        job_ = job;
        serial = ++jobSerial_;
    }
    wake_.notify_all();
    return serial;
}

PassTotals RenderWorker::totals() const {
    std::lock_guard lock(mutex_);
    return totals_;
}

bool RenderWorker::takeLatest(ShownImage& out) {
    std::lock_guard lock(mutex_);
    if (latest_.serial <= out.serial) {
        return false;
    }
    std::swap(out, latest_);
    return true;
}

void RenderWorker::run() {
    lowerThisThreadsPriority();
    // The accumulation: one film per side of the picture (the second only for a split job), each
    // holding film.samples() samples per pixel of its side's settings (core restarts a film when
    // a pass is cancelled, and a restart costs nothing).
    RenderJob job;
    uint64_t takenSerial = 0;
    Film films[2];
    ParkedFilm parked;                // the last picture replaced, resumed when its job comes back
    std::vector<uint8_t> sideBgra[2]; // each side's display bytes, for a split picture
    bool filmsValid = false;
    bool previewTried = false;
    double secondsPerPixel = 0.0; // of one sample, measured by the last pass; 0 before any
    uint64_t published = 0;
    Film previewFilm;
    std::vector<uint8_t> previewBgra[2];
    Framebuffer sideMeans[2]; // each side's mean, for a difference (previews too)
    ShownImage staging;

    const auto publish = [&](ShownImage& picture) {
        {
            std::lock_guard lock(mutex_);
            picture.serial = ++published;
            std::swap(latest_, picture);
        }
        if (onPicture_) {
            onPicture_();
        }
    };
    const auto setInPreview = [&](bool running) {
        std::lock_guard lock(mutex_);
        inPreview_ = running;
    };
    const auto setInShortFirstPass = [&](bool running) {
        std::lock_guard lock(mutex_);
        inShortFirstPass_ = running;
    };
    // Counts a pass (or preview) that took `seconds`, or was cancelled when `seconds` is < 0.
    const auto tally = [&](Tally PassTotals::*which, double seconds) {
        std::lock_guard lock(mutex_);
        if (seconds < 0.0) {
            ++totals_.cancelled;
        } else {
            (totals_.*which).add(seconds);
        }
    };
    const auto sidesOf = [](const RenderJob& j) { return j.compare ? 2 : 1; };
    const auto differenceOf = [](const RenderJob& j) {
        return j.compare && j.compareMode == CompareMode::Difference;
    };
    // The side whose film gets the next pass: the one with fewer samples below its cap (the
    // left on a tie), or -1 when every side has reached its cap.
    const auto nextSide = [&](const RenderJob& j) {
        int side = -1;
        for (int i = 0; i < sidesOf(j); ++i) {
            const uint32_t cap = static_cast<uint32_t>(sideSettings(j, i).samplesPerPixel);
            if (films[i].samples() < cap &&
                (side < 0 || films[i].samples() < films[side].samples())) {
                side = i;
            }
        }
        return side;
    };

    for (;;) {
        uint64_t serial = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] {
                return quit_ || (job_.scene &&
                                 (jobSerial_ != takenSerial ||
                                  (filmsValid && samePicture(job_, job) && nextSide(job_) >= 0)));
            });
            if (quit_) {
                return;
            }
            bool restart = !filmsValid || !samePicture(job_, job);
            for (int i = 0; i < sidesOf(job_) && !restart; ++i) {
                restart = static_cast<uint32_t>(sideSettings(job_, i).samplesPerPixel) <
                          films[i].samples();
            }
            if (restart && parked.exchange(job, filmsValid, job_, films[0])) {
                restart = false; // back to the picture replaced last: its samples resume
                filmsValid = true;
            }
            job = job_;
            serial = takenSerial = jobSerial_;
            cancel_.store(false);
            if (restart) {
                for (int i = 0; i < sidesOf(job); ++i) {
                    const RenderSettings& side = sideSettings(job, i);
                    films[i].reset(side.width, side.height, filmLayersFor(side));
                }
                filmsValid = true;
                previewTried = false;
            }
            // Decided with the job, under the same lock, so no submit slips in between. A pass
            // of unknown cost (none measured yet) counts as too long.
            const double expected = secondsPerPixel * static_cast<double>(pixelCount(job.settings));
            inShortFirstPass_ = films[0].samples() == 0 && secondsPerPixel > 0.0 &&
                                expected <= previewBudgetSeconds_;
        }
        const RenderSettings& settings = job.settings;
        const LoadedScene& loaded = *job.scene;
        const int sides = sidesOf(job);
        PassOptions pass;
        pass.cancel = &cancel_;
        pass.emitters = &loaded.emitters;

        if (films[0].samples() == 0 && !previewTried) {
            previewTried = true;
            const int k = previewDivisor(
                secondsPerPixel * static_cast<double>(pixelCount(settings)), previewBudgetSeconds_);
            if (k > 1) {
                // Each side at 1/k resolution, enlarged by pixel replication.
                RayCounts counts;
                const auto start = Clock::now();
                bool finished = true;
                int smallWidth = 0;
                int smallHeight = 0;
                setInPreview(true);
                for (int i = 0; i < sides && finished; ++i) {
                    RenderSettings small = sideSettings(job, i);
                    small.width = (settings.width + k - 1) / k;
                    small.height = (settings.height + k - 1) / k;
                    smallWidth = small.width;
                    smallHeight = small.height;
                    previewFilm.reset(small.width, small.height, filmLayersFor(small));
                    finished =
                        renderPass(loaded.scene, loaded.bvh, small, previewFilm, &counts, pass);
                    previewBgra[i].resize(4 * pixelCount(small));
                    previewFilm.toDisplay(previewBgra[i], small.display, small.exposure,
                                          PixelOrder::Bgra);
                    if (differenceOf(job)) {
                        previewFilm.mean(sideMeans[i]);
                    }
                }
                setInPreview(false);
                if (!finished) {
                    tally(&PassTotals::previews, -1.0);
                    continue;
                }
                const double seconds = secondsSince(start);
                tally(&PassTotals::previews, seconds);
                secondsPerPixel = seconds / static_cast<double>(sides * smallWidth * smallHeight);
                if (differenceOf(job)) {
                    Framebuffer difference;
                    composeDifference(sideMeans[0], sideMeans[1], job.differenceScale, difference,
                                      previewBgra[0], PixelOrder::Bgra);
                } else if (sides == 2) {
                    composeSplit(previewBgra[0], previewBgra[1], smallWidth, smallHeight,
                                 job.divider, previewBgra[0]);
                }
                enlarge(previewBgra[0], smallWidth, smallHeight, settings.width, settings.height,
                        staging.bgra);
                staging.linear = Framebuffer();
                staging.settings = settings;
                staging.settings.width = smallWidth;
                staging.settings.height = smallHeight;
                staging.compare.reset();
                staging.divider = job.divider;
                staging.compareMode = job.compareMode;
                staging.differenceScale = job.differenceScale;
                staging.scene = job.scene;
                staging.jobSerial = serial;
                staging.preview = true;
                staging.final = false;
                staging.passSeconds = seconds;
                staging.raysPerSecond = raysPerSecond(counts, seconds);
                staging.noise = NoiseEstimate();
                staging.meanIndirect = glm::vec3(0.0f);
                publish(staging);
                continue;
            }
        }

        double seconds = 0.0;
        RayCounts counts;
        bool displayed = false; // the display bytes already show the films
        if (const int side = nextSide(job); side >= 0) {
            // The pass writes the display bytes tile by tile, on the tracing threads: straight
            // into the picture for one side, into the side's own bytes for a split.
            std::vector<uint8_t>& bytes = sides == 1 ? staging.bgra.pixels : sideBgra[side];
            bytes.resize(4 * pixelCount(settings));
            PassOptions full = pass;
            full.displayRgba = bytes;
            full.displayOrder = PixelOrder::Bgra;
            full.samples =
                passSamples(films[side].samples(),
                            static_cast<uint32_t>(sideSettings(job, side).samplesPerPixel),
                            secondsPerPixel, pixelCount(settings));
            const auto start = Clock::now();
            const bool complete = renderPass(loaded.scene, loaded.bvh, sideSettings(job, side),
                                             films[side], &counts, full);
            setInShortFirstPass(false);
            if (!complete) {
                tally(&PassTotals::passes, -1.0);
                continue;
            }
            seconds = secondsSince(start);
            tally(&PassTotals::passes, seconds);
            secondsPerPixel = seconds / (static_cast<double>(pixelCount(settings)) * full.samples);
            displayed = sides == 1 || films[1 - side].samples() > 0;
            if (sides == 2 && films[1 - side].samples() > 0) {
                // The other side's bytes may be of another display transform: made again below
                // only when nothing was traced for it with this job's.
                const RenderSettings& other = sideSettings(job, 1 - side);
                sideBgra[1 - side].resize(4 * pixelCount(settings));
                films[1 - side].toDisplay(sideBgra[1 - side], other.display, other.exposure,
                                          PixelOrder::Bgra);
            }
        }
        // A new pass, or a new job that keeps the samples (display, cap, threads, divider): show
        // it.
        staging.bgra.width = settings.width;
        staging.bgra.height = settings.height;
        const bool difference = differenceOf(job);
        if (sides == 1 && !displayed) {
            staging.bgra.pixels.resize(4 * pixelCount(settings));
            films[0].toDisplay(staging.bgra.pixels, settings.display, settings.exposure,
                               PixelOrder::Bgra);
        } else if (difference) {
            // The signed difference of the two sides' means: the bytes and the linear picture.
            films[0].mean(sideMeans[0]);
            films[1].mean(sideMeans[1]);
            staging.bgra.pixels.resize(4 * pixelCount(settings));
            composeDifference(sideMeans[0], sideMeans[1], job.differenceScale, staging.linear,
                              staging.bgra.pixels, PixelOrder::Bgra);
        } else if (sides == 2) {
            for (int i = 0; i < 2; ++i) {
                const RenderSettings& side = sideSettings(job, i);
                if (!displayed || films[i].samples() == 0) {
                    sideBgra[i].resize(4 * pixelCount(settings));
                    films[i].toDisplay(sideBgra[i], side.display, side.exposure, PixelOrder::Bgra);
                }
            }
            staging.bgra.pixels.resize(4 * pixelCount(settings));
            composeSplit(sideBgra[0], sideBgra[1], settings.width, settings.height, job.divider,
                         staging.bgra.pixels);
        }
        if (difference) {
            if (!job.keepLinear) {
                staging.linear = Framebuffer();
            }
        } else if (job.keepLinear) {
            films[0].mean(staging.linear);
            if (sides == 2) {
                Framebuffer right;
                films[1].mean(right);
                composeSplit(staging.linear, right, job.divider);
            }
        } else {
            staging.linear = Framebuffer();
        }
        // The noise and the mean N of the path-traced side (the left one unless only the right
        // side is path traced).
        const int pathSide = sides == 2 && job.compare->integrator == Integrator::Path &&
                                     job.settings.integrator != Integrator::Path
                                 ? 1
                                 : 0;
        staging.noise = films[pathSide].noise();
        staging.meanIndirect = films[pathSide].meanIndirect();
        staging.settings = settings;
        staging.settings.samplesPerPixel = static_cast<int>(films[0].samples());
        staging.compare = job.compare;
        if (staging.compare) {
            staging.compare->samplesPerPixel = static_cast<int>(films[1].samples());
        }
        staging.divider = job.divider;
        staging.compareMode = job.compareMode;
        staging.differenceScale = job.differenceScale;
        staging.scene = job.scene;
        staging.jobSerial = serial;
        staging.preview = false;
        staging.final = nextSide(job) < 0;
        staging.passSeconds = seconds;
        staging.raysPerSecond = raysPerSecond(counts, seconds);
        publish(staging);
    }
}

} // namespace raylab::viewer
