#pragma once
// A scene ready to render: its triangles and their BVH, built once and shared read-only between
// the UI thread and the render thread (the render thread keeps it alive while a pass runs).

#include "core/bvh/bvh.h"
#include "core/lights/emitters.h"
#include "core/scene.h"
#include "io/mesh_import.h"

#include <memory>
#include <string>

namespace raylab::viewer {

struct LoadedScene {
    std::string source; // "cornell" or the mesh path, as given
    Scene scene;
    Bvh bvh;
    EmitterTable emitters; // buildEmitterTable(scene)
};

struct SceneLoadResult {
    std::shared_ptr<const LoadedScene> scene; // null when loading failed
    std::string error;                        // one line when scene is null
    std::string warnings;                     // the loader's skipped-element lines; may be empty
    double seconds = 0.0;                     // load and BVH build, wall clock
};

// Loads `source` ("cornell" or a mesh file, read by raylab-import under `limits`) and builds its
// BVH. Blocks until done or cancelled (control.cancelled); never throws for a bad file (the error
// is in the result).
SceneLoadResult loadSceneForViewer(const std::string& source, const ImportLimits& limits = {},
                                   const ImportControl& control = {});

} // namespace raylab::viewer
