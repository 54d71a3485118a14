#include "loaded_scene.h"

#include <chrono>
#include <exception>

namespace raylab::viewer {

SceneLoadResult loadSceneForViewer(const std::string& source, const ImportLimits& limits,
                                   const ImportControl& control) {
    const auto start = std::chrono::steady_clock::now();
    SceneLoadResult result;
    try {
        auto loaded = std::make_shared<LoadedScene>();
        loaded->source = source;
        if (!loadScene(source, limits, loaded->scene, result.warnings, result.error, control)) {
            return result;
        }
        loaded->bvh = buildBvh(loaded->scene);
        loaded->emitters = buildEmitterTable(loaded->scene);
        result.scene = std::move(loaded);
    } catch (const std::exception& e) {
        // Out of memory on a huge file, for instance: report it instead of ending the viewer.
        result.error = source + ": " + e.what();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace raylab::viewer
