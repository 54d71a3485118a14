#include "scene_loader.h"

namespace raylab::viewer {

SceneLoader::~SceneLoader() {
    if (thread_.joinable()) {
        thread_.join();
    }
}

bool SceneLoader::start(const std::string& source) {
    std::lock_guard lock(mutex_);
    if (running_) {
        return false;
    }
    if (thread_.joinable()) {
        thread_.join(); // the previous load has finished: running_ is false
    }
    running_ = true;
    result_.reset();
    thread_ = std::thread([this, source] {
        SceneLoadResult result = loadSceneForViewer(source);
        {
            std::lock_guard done(mutex_);
            result_ = std::move(result);
            running_ = false;
        }
        if (onDone_) {
            onDone_();
        }
    });
    return true;
}

bool SceneLoader::busy() const {
    std::lock_guard lock(mutex_);
    return running_;
}

std::optional<SceneLoadResult> SceneLoader::poll() {
    std::lock_guard lock(mutex_);
    std::optional<SceneLoadResult> out = std::move(result_);
    result_.reset();
    return out;
}

} // namespace raylab::viewer
