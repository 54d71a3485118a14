#pragma once
// The viewer's main loop on the UI thread: events, panel, input, render jobs for the render
// thread, the newest picture uploaded and drawn, screenshots, and the scripted end.
//
// The UI draws a frame only when one is wanted (redraw_schedule.h): a new picture of the tracer
// (the render thread wakes the UI thread), an input or window event and the kFramesAfterEvent
// frames after it that Dear ImGui needs, a held mouse button, a blinking text cursor, a resize,
// a loaded scene. Frames are paced to at most kFramesPerSecond; an idle window draws nothing, so
// the tracer gets the CPU that a software GL driver would spend redrawing identical frames.
// While minimised it draws nothing. Scripted runs (--frames) and replays (--replay) draw every
// frame at the paced rate.
//
// Scripted end (--frames N): the viewer quits after N shown frames. With --screenshot FILE or
// --readback FILE it keeps going after N until the picture on screen is final (the sample cap
// reached for the current settings), so the saved files are deterministic. --readback saves the
// framebuffer of that last frame, read back with glReadPixels after drawing, rows from the top.
// Without --frames, --screenshot saves the last shown finished picture on quitting.

#include "io/command_line.h"
#include "io/session_recording.h"
#include "loaded_scene.h"

#include <memory>
#include <optional>

namespace raylab::viewer {

inline constexpr double kFramesPerSecond = 60.0;
// Frames drawn after an input or window event (after a key only when the panel has the
// keyboard; otherwise one): Dear ImGui shows some of its effects (hover, activation, a panel's
// new size) one or two frames late.
inline constexpr int kFramesAfterEvent = 3;
// While a text field is active, its cursor blinks: a frame at least this often (seconds).
inline constexpr double kTextCursorSeconds = 0.1;
// With nothing wanted, the UI thread still wakes this often (seconds) to look around; it draws
// nothing then.
inline constexpr double kIdleWakeSeconds = 0.5;
// How often the panel's line of a running load ("loading FILE  3.2 s") is redrawn, in seconds.
inline constexpr double kLoadClockSeconds = 0.1;

// Opens the window and runs until it closes, Escape, or the script ends (viewer_loop.h). The
// command line's settings must be valid and already placed for the scene; settings.samplesPerPixel
// is the sample cap. With `replay` (--replay: its first state in `command`) the window plays the
// recording back, writing its screenshots again, and ends with it; --record writes the session's
// recording on quitting. Returns the process exit code (0, or 1 when the window cannot open, a
// requested file cannot be written, or a replay's scene or screenshot fails).
int runViewer(const CommandLine& command, std::shared_ptr<const LoadedScene> scene,
              std::optional<SessionRecording> replay = std::nullopt);

} // namespace raylab::viewer
