// raylab: the interactive viewer. Parses the command line, loads the scene (a bad one ends here
// with one line and exit code 1), and runs the window (viewer_app.h).

#include "io/atomic_file.h"
#include "io/command_line.h"
#include "io/load_progress.h"
#include "io/session_recording.h"
#include "loaded_scene.h"
#include "viewer_app.h"

#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

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
    for (const std::string& file : {command.viewer.stats, command.viewer.record}) {
        if (std::string why; !file.empty() && !checkWritable(file, why)) {
            std::fprintf(stderr, "raylab: %s\n", why.c_str());
            return 1;
        }
    }
    // A replay starts as its recording did: its first state's scene and settings.
    std::optional<SessionRecording> replay;
    if (!command.viewer.replay.empty()) {
        replay.emplace();
        if (!loadRecording(command.viewer.replay, *replay, error)) {
            std::fprintf(stderr, "raylab: %s\n", error.c_str());
            return 1;
        }
        const RecordedState& first = *replay->events.front().state;
        command.scene = first.scene;
        command.settings = first.settings; // complete: not placed for the scene again
        command.bookmarks = first.bookmarks;
        command.observedLabCamera = first.labCamera;
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
    if (const std::string why =
            replay ? std::string() : finishSettings(loaded.scene->scene, command);
        !why.empty()) {
        std::fprintf(stderr, "raylab: %s\n", why.c_str());
        return 2;
    }
    return runViewer(command, loaded.scene, std::move(replay));
}
