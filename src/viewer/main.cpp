// raylab: the interactive viewer. Parses the command line, loads the scene (a bad one ends here
// with one line and exit code 1), and runs the window (viewer_app.h).

#include "io/atomic_file.h"
#include "io/command_line.h"
#include "io/load_progress.h"
#include "loaded_scene.h"
#include "viewer_app.h"

#include <csignal>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    using namespace raylab;
    using namespace raylab::viewer;
    // A write to a closed pipe or socket (stdout piped into a program that ended, an X server
    // that went away) fails with EPIPE and is reported (Xlib prints which server and exits)
    // instead of killing the viewer without a word.
    std::signal(SIGPIPE, SIG_IGN);
    CommandLine command;
    std::string error;
    if (const int status = parseCommandLine(argc, argv, Program::Viewer, command, error);
        status != 0) {
        std::fprintf(stderr, "raylab: %s\n", error.c_str());
        return status;
    }
    if (command.help) {
        std::fputs(usage(Program::Viewer).c_str(), stdout);
        return 0;
    }
    if (std::string why;
        !command.viewer.stats.empty() && !checkWritable(command.viewer.stats, why)) {
        std::fprintf(stderr, "raylab: %s\n", why.c_str());
        return 1;
    }
    SceneLoadResult loaded;
    {
        LoadProgressLine progress("raylab", command.scene); // erased at the end of this block
        loaded = loadSceneForViewer(command.scene, command.importLimits, progress.control());
    }
    if (!loaded.scene) {
        std::fprintf(stderr, "raylab: %s\n", loaded.error.c_str());
        return 1;
    }
    if (!loaded.warnings.empty()) {
        std::fprintf(stderr, "raylab: %s\n", loaded.warnings.c_str());
    }
    // A mesh is framed except for what the command line gave, as raylab-render does.
    if (const std::string why = finishSettings(loaded.scene->scene, command); !why.empty()) {
        std::fprintf(stderr, "raylab: %s\n", why.c_str());
        return 2;
    }
    return runViewer(command, loaded.scene);
}
