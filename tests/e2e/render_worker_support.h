#pragma once
// What the render thread's tests share: the lab's box as a loaded scene, and waiting for a job's
// final picture.

#include "core/cornell_box.h"
#include "loaded_scene.h"
#include "render_worker.h"

#include <chrono>
#include <gtest/gtest.h>
#include <memory>
#include <thread>

namespace raylab::viewer::test {

inline std::shared_ptr<const LoadedScene> labBox() {
    auto loaded = std::make_shared<LoadedScene>();
    loaded->source = "cornell";
    loaded->scene = makeCornellBox();
    loaded->bvh = buildBvh(loaded->scene);
    return loaded;
}

// Waits (at most `seconds`) for a final picture of job `serial`.
inline ShownImage waitFinal(RenderWorker& worker, uint64_t serial, int seconds = 30) {
    ShownImage shown;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        worker.takeLatest(shown);
        if (shown.jobSerial == serial && shown.final && !shown.preview) {
            return shown;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ADD_FAILURE() << "no final picture within " << seconds << " s";
    return shown;
}

} // namespace raylab::viewer::test
