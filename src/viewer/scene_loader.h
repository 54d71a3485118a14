#pragma once
// Loads a scene on a background thread so the window stays responsive while a big mesh is read
// and its BVH built. One load at a time; the UI thread polls for the result.

#include "loaded_scene.h"

#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

namespace raylab::viewer {

class SceneLoader {
public:
    // onDone, when set, is called on the loading thread once a result is ready to poll (so a
    // waiting UI can wake up); it must be thread-safe and quick.
    explicit SceneLoader(std::function<void()> onDone = {}) : onDone_(std::move(onDone)) {}
    SceneLoader(const SceneLoader&) = delete;
    SceneLoader& operator=(const SceneLoader&) = delete;
    // Waits for a load in progress (a mesh load cannot be interrupted).
    ~SceneLoader();

    // Starts loading `source`. Returns false (and does nothing) while another load runs.
    bool start(const std::string& source);
    bool busy() const;
    // The finished load's result, once; empty while loading or when nothing was started.
    std::optional<SceneLoadResult> poll();

private:
    const std::function<void()> onDone_;
    mutable std::mutex mutex_;
    std::thread thread_;
    bool running_ = false;
    std::optional<SceneLoadResult> result_;
};

} // namespace raylab::viewer
