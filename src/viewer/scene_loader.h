#pragma once
// Loads a scene on a background thread so the window stays responsive while a mesh is read (by
// raylab-import, io/mesh_import.h) and its BVH built. One load counts at a time: a new one
// replaces a running one, which is cancelled (its helper killed) and whose result is dropped.
// The UI thread polls for the result and never waits for a load, not even when it quits.

#include "loaded_scene.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace raylab::viewer {

// The load that runs, for the panel.
struct LoadProgress {
    std::string source;   // as given to start
    double seconds = 0.0; // wall clock since start
};

class SceneLoader {
public:
    // onDone, when set, is called on a loading thread once a result is ready to poll (so a
    // waiting UI can wake up); it must be thread-safe and quick. It is never called once the
    // loader is destroyed.
    explicit SceneLoader(const ImportLimits& limits, std::function<void()> onDone = {});
    SceneLoader(const SceneLoader&) = delete;
    SceneLoader& operator=(const SceneLoader&) = delete;
    // Cancels a running load and returns at once, or after at most kCloseGraceSeconds when the
    // load is past its import (building a BVH cannot be stopped; that thread then finishes alone
    // and its result is dropped).
    ~SceneLoader();

    // Starts loading `source`, cancelling a running load first.
    void start(const std::string& source);
    // Cancels the running load, if any: its helper is killed within about 20 ms and poll gives
    // nothing for it. Returns whether there was one.
    bool cancel();
    bool busy() const;
    std::optional<LoadProgress> progress() const;
    // The finished load's result, once; empty while loading or when nothing was started.
    std::optional<SceneLoadResult> poll();

    static constexpr double kCloseGraceSeconds = 0.2;

private:
    struct Shared;
    struct Load;
    const ImportLimits limits_;
    std::shared_ptr<Shared> shared_; // also held by the loading threads, which may outlive this
};

} // namespace raylab::viewer
