#include "render_worker.h"

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
    return a.scene == b.scene && sameSamples(a.settings, b.settings);
}

bool sameJob(const RenderJob& a, const RenderJob& b) {
    return a.scene == b.scene && a.settings == b.settings;
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
    // The accumulation: `film` holds film.samples() samples per pixel of `job` (core restarts it
    // when a pass is cancelled, and a restart costs nothing).
    RenderJob job;
    uint64_t takenSerial = 0;
    Film film;
    bool filmValid = false;
    bool previewTried = false;
    double secondsPerPixel = 0.0; // measured by the last pass, 0 before any
    uint64_t published = 0;
    Film previewFilm;
    std::vector<uint8_t> previewBgra;
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

    for (;;) {
        uint64_t serial = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] {
                return quit_ ||
                       (job_.scene &&
                        (jobSerial_ != takenSerial ||
                         film.samples() < static_cast<uint32_t>(job_.settings.samplesPerPixel)));
            });
            if (quit_) {
                return;
            }
            const bool restart =
                !filmValid || !samePicture(job_, job) ||
                static_cast<uint32_t>(job_.settings.samplesPerPixel) < film.samples();
            job = job_;
            serial = takenSerial = jobSerial_;
            cancel_.store(false);
            if (restart) {
                film.reset(job.settings.width, job.settings.height, filmLayersFor(job.settings));
                filmValid = true;
                previewTried = false;
            }
            const uint32_t samples = film.samples();
            // Decided with the job, under the same lock, so no submit slips in between. A pass
            // of unknown cost (none measured yet) counts as too long.
            const double expected = secondsPerPixel * static_cast<double>(pixelCount(job.settings));
            inShortFirstPass_ =
                samples == 0 && secondsPerPixel > 0.0 && expected <= previewBudgetSeconds_;
        }
        const RenderSettings& settings = job.settings;
        const LoadedScene& loaded = *job.scene;
        PassOptions pass;
        pass.cancel = &cancel_;
        pass.emitters = &loaded.emitters;

        if (film.samples() == 0 && !previewTried) {
            previewTried = true;
            const int k = previewDivisor(
                secondsPerPixel * static_cast<double>(pixelCount(settings)), previewBudgetSeconds_);
            if (k > 1) {
                RenderSettings small = settings;
                small.width = (settings.width + k - 1) / k;
                small.height = (settings.height + k - 1) / k;
                previewFilm.reset(small.width, small.height, filmLayersFor(small));
                RayCounts counts;
                const auto start = Clock::now();
                setInPreview(true);
                const bool finished =
                    renderPass(loaded.scene, loaded.bvh, small, previewFilm, &counts, pass);
                setInPreview(false);
                if (!finished) {
                    tally(&PassTotals::previews, -1.0);
                    continue;
                }
                const double seconds = secondsSince(start);
                tally(&PassTotals::previews, seconds);
                secondsPerPixel = seconds / static_cast<double>(pixelCount(small));
                previewBgra.resize(4 * pixelCount(small));
                previewFilm.toDisplay(previewBgra, settings.display, settings.exposure,
                                      PixelOrder::Bgra);
                enlarge(previewBgra, small.width, small.height, settings.width, settings.height,
                        staging.bgra);
                staging.linear = Framebuffer();
                staging.settings = small;
                staging.scene = job.scene;
                staging.jobSerial = serial;
                staging.preview = true;
                staging.final = false;
                staging.passSeconds = seconds;
                staging.raysPerSecond = raysPerSecond(counts, seconds);
                publish(staging);
                continue;
            }
        }

        double seconds = 0.0;
        RayCounts counts;
        bool displayed = false; // staging.bgra already shows the sums
        if (film.samples() < static_cast<uint32_t>(settings.samplesPerPixel)) {
            // The pass writes the display bytes tile by tile, on the tracing threads.
            staging.bgra.pixels.resize(4 * pixelCount(settings));
            PassOptions full = pass;
            full.displayRgba = staging.bgra.pixels;
            full.displayOrder = PixelOrder::Bgra;
            const auto start = Clock::now();
            const bool complete =
                renderPass(loaded.scene, loaded.bvh, settings, film, &counts, full);
            setInShortFirstPass(false);
            if (!complete) {
                tally(&PassTotals::passes, -1.0);
                continue;
            }
            seconds = secondsSince(start);
            tally(&PassTotals::passes, seconds);
            secondsPerPixel = seconds / static_cast<double>(pixelCount(settings));
            displayed = true;
        }
        // A new pass, or a new job that keeps the samples (display, cap, threads): show it.
        staging.bgra.width = settings.width;
        staging.bgra.height = settings.height;
        if (!displayed) {
            staging.bgra.pixels.resize(4 * pixelCount(settings));
            film.toDisplay(staging.bgra.pixels, settings.display, settings.exposure,
                           PixelOrder::Bgra);
        }
        if (job.keepLinear) {
            film.mean(staging.linear);
        } else {
            staging.linear = Framebuffer();
        }
        const uint32_t samples = film.samples();
        staging.noise = film.noise();
        staging.meanIndirect = film.meanIndirect();
        staging.settings = settings;
        staging.settings.samplesPerPixel = static_cast<int>(samples);
        staging.scene = job.scene;
        staging.jobSerial = serial;
        staging.preview = false;
        staging.final = samples >= static_cast<uint32_t>(settings.samplesPerPixel);
        staging.passSeconds = seconds;
        staging.raysPerSecond = raysPerSecond(counts, seconds);
        publish(staging);
    }
}

} // namespace raylab::viewer
