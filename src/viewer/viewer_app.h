#pragma once
// The viewer's main loop on the UI thread: events, panel, input, render jobs for the render
// thread, the newest picture uploaded and drawn, screenshots, and the scripted end.
//
// The UI redraws at most kFramesPerSecond times a second (and at least that often while a pass
// runs, since the tracer works on its own thread); while minimised it draws nothing.
//
// Scripted end (--frames N): the viewer quits after N shown frames. With --screenshot FILE or
// --readback FILE it keeps going after N until the picture on screen is final (the sample cap
// reached for the current settings), so the saved files are deterministic. --readback saves the
// framebuffer of that last frame, read back with glReadPixels after drawing, rows from the top.
// Without --frames, --screenshot saves the last shown finished picture on quitting.

#include "loaded_scene.h"
#include "viewer_options.h"

#include <memory>

namespace raylab::viewer {

inline constexpr double kFramesPerSecond = 60.0;

// Opens the window and runs until it closes, Escape, or the script ends. `settings` in options
// must be valid and already placed for the scene. Returns the process exit code (0, or 1 when the
// window cannot open or a requested file cannot be written).
int runViewer(const ViewerOptions& options, std::shared_ptr<const LoadedScene> scene);

} // namespace raylab::viewer
