#include "scene_loader.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <utility>

namespace raylab::viewer {

namespace {
using Clock = std::chrono::steady_clock;
} // namespace

// One started load; its thread and the loader share it.
struct SceneLoader::Load {
    std::string source;
    Clock::time_point started;
    std::atomic<bool> cancelled{false}; // read by the import's control every ~20 ms
};

// What the loading threads and the loader share; everything below the mutex is guarded by it.
struct SceneLoader::Shared {
    std::function<void()> onDone;
    std::mutex mutex;
    std::condition_variable threadEnded;
    std::shared_ptr<Load> current;         // the load whose result counts; null when none runs
    std::optional<SceneLoadResult> result; // current's, once finished, until polled
    int threads = 0;                       // loading threads not yet ended
    bool closed = false;                   // the loader is gone: no result, no onDone
};

SceneLoader::SceneLoader(const ImportLimits& limits, std::function<void()> onDone)
    : limits_(limits), shared_(std::make_shared<Shared>()) {
    shared_->onDone = std::move(onDone);
}

SceneLoader::~SceneLoader() {
    std::unique_lock lock(shared_->mutex);
    shared_->closed = true;
    if (shared_->current) {
        shared_->current->cancelled = true;
        shared_->current.reset();
    }
    shared_->threadEnded.wait_for(lock, std::chrono::duration<double>(kCloseGraceSeconds),
                                  [this] { return shared_->threads == 0; });
}

void SceneLoader::start(const std::string& source) {
    auto load = std::make_shared<Load>();
    load->source = source;
    load->started = Clock::now();
    {
        std::lock_guard lock(shared_->mutex);
        if (shared_->current) {
            shared_->current->cancelled = true;
        }
        shared_->current = load;
        shared_->result.reset();
        ++shared_->threads;
    }
    // Detached: a thread that is building a BVH when its load is replaced or the viewer quits
    // finishes alone; it holds what it touches (shared, load) itself.
    std::thread([shared = shared_, load, limits = limits_] {
        ImportControl control;
        control.cancelled = [load] { return load->cancelled.load(); };
        SceneLoadResult result = loadSceneForViewer(load->source, limits, control);
        std::lock_guard lock(shared->mutex);
        --shared->threads;
        shared->threadEnded.notify_all();
        if (shared->closed || shared->current != load) {
            return; // cancelled or replaced: nobody wants this result
        }
        shared->result = std::move(result);
        shared->current.reset();
        if (shared->onDone) {
            shared->onDone(); // under the lock, so never after the destructor's closed
        }
    }).detach();
}

bool SceneLoader::cancel() {
    std::lock_guard lock(shared_->mutex);
    if (!shared_->current) {
        return false;
    }
    shared_->current->cancelled = true;
    shared_->current.reset();
    return true;
}

bool SceneLoader::busy() const {
    std::lock_guard lock(shared_->mutex);
    return shared_->current != nullptr;
}

std::optional<LoadProgress> SceneLoader::progress() const {
    std::lock_guard lock(shared_->mutex);
    if (!shared_->current) {
        return std::nullopt;
    }
    return LoadProgress{
        shared_->current->source,
        std::chrono::duration<double>(Clock::now() - shared_->current->started).count()};
}

std::optional<SceneLoadResult> SceneLoader::poll() {
    std::lock_guard lock(shared_->mutex);
    std::optional<SceneLoadResult> out = std::move(shared_->result);
    shared_->result.reset();
    return out;
}

} // namespace raylab::viewer
