#pragma once
// The viewer's main loop (viewer_app.h) as one object: the window and its GL parts, the state the
// frames share, and the loop's named steps. run() is
//     wait for a wake-up; poll the tracer; poll the scene loader;
//     when a frame is due: begin it, handle input, draw it; schedule the next wake-up;
// until a quit, the end of a script (--frames) or the end of a replay (--replay). The steps live
// in viewer_loop.cpp (the loop, the tracer, the loader, scheduling, the end), viewer_input.cpp
// (drops, keys, mouse, the panel, the replay's events) and viewer_draw.cpp (the picture, its
// overlays, screenshots, the swap).

#include "core/integrators/pixel_inspection.h"
#include "gl_overlay.h"
#include "gl_window.h"
#include "held_keys.h"
#include "image_quad.h"
#include "input.h"
#include "io/command_line.h"
#include "io/session_recording.h"
#include "key_relay.h"
#include "loaded_scene.h"
#include "observer_view.h"
#include "orbit_controls.h"
#include "panel.h"
#include "panel_context.h"
#include "panel_layer.h"
#include "panel_numbers.h"
#include "picture_readouts.h"
#include "redraw_schedule.h"
#include "render_worker.h"
#include "run_stats.h"
#include "scene_loader.h"
#include "session_recorder.h"
#include "session_replay.h"
#include "shown_image.h"
#include "view_layout.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace raylab::viewer {

class ViewerLoop {
public:
    // `command`: valid settings placed for `scene`. `replay`: a recording to play back, whose
    // first state `command` already holds.
    ViewerLoop(const CommandLine& command, std::shared_ptr<const LoadedScene> scene,
               std::optional<SessionRecording> replay);
    ViewerLoop(const ViewerLoop&) = delete;
    ViewerLoop& operator=(const ViewerLoop&) = delete;

    // Opens the window (hidden until sized for the panel), Dear ImGui and the GL objects. False
    // with a one-line error.
    bool open(std::string& error);
    // Runs the loop; returns the process exit code (viewer_app.h).
    int run();

private:
    using Clock = std::chrono::steady_clock;
    using TimePoint = Clock::time_point;

    static double secondsBetween(TimePoint from, TimePoint to) {
        return std::chrono::duration<double>(to - from).count();
    }
    static TimePoint after(TimePoint t, double seconds) {
        return t +
               std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    }

    // The loop's steps, in order (viewer_loop.cpp unless said otherwise).
    void waitForWake();
    void pollTracer();
    void pollLoader();
    bool frameDue();    // minimising, resizing and the schedule: whether this wake-up draws
    void beginFrame();  // the layout, Dear ImGui's frame, the newest picture uploaded
    void handleInput(); // viewer_input.cpp, as beginFrame
    void drawFrame();   // viewer_draw.cpp
    void scheduleNextWake();
    int finish();

    // Parts of handleInput (viewer_input.cpp).
    void applyDrops(const std::vector<std::string>& dropped);
    void applyKeysAndMouse(const InputEvents& events);
    void applyHeldKeys(const std::vector<NavKeyChange>& changes);
    void applyDrag(bool start, RenderSettings& settings);
    void drawPanelColumn();
    void applyReplay(const InputEvents& events);
    void inspect();

    // Parts of drawFrame (viewer_draw.cpp).
    void uploadPicture();
    void drawOverlays();
    void saveScreenshots(bool current);
    void countFrame(TimePoint wokeAt);

    // Hands the tracer the job of the panel's settings (or the replay's state) when it differs
    // from the last one; notes it for --record.
    void submitJob();
    // Kills the running load's helper; the scene, camera, samples and settings stay.
    void cancelLoad();
    void setStatus(const std::string& text, bool isError);
    // The panel's scale: --ui-scale, else the window's content scale per framebuffer scale.
    float monitorUiScale() const;
    // The window's size (screen coordinates) that shows a width x height picture with the
    // panel's column, when shown, beside it.
    void sizeWindowFor(int width, int height);
    ViewLayout layoutOf(int framebufferWidth, int framebufferHeight) const;

    const CommandLine& command_;
    const ViewerFlags& flags_; // the viewer's own options
    std::shared_ptr<const LoadedScene> scene_;
    const bool scripted_;   // --frames N
    const bool needsFinal_; // --screenshot or --readback: the script ends on a final picture

    // The window and its GL parts, in the order they are made (and unmade in reverse).
    GlWindow window_;
    InputCollector input_;
    std::optional<PanelContext> gui_;
    ImageQuad quad_;
    PanelLayer panelLayer_; // the panel drawn, its cached pixels, the copies of numbers it shows
    OverlayLines overlayLines_;
    std::optional<KeyRelay> keys_;

    // The panel and what it shows.
    PanelState panel_;
    bool showPanel_;
    float uiScale_ = 1.0f;
    float panelUnits_ = kPanelColumnWidth;      // the column's width at UI scale 1 (its edge drags)
    bool showKeys_ = false;                     // the list of keys and mouse gestures (H)
    PanelNumbers numbers_;                      // live: every frame and picture
    std::optional<PixelInspection> inspection_; // the inspected pixel's numbers, this frame

    // Navigation and the camera's views.
    ObserverView observer_; // O, and each camera's undo history
    OrbitControls orbit_;   // right drag orbits, middle drag pans
    PictureReadouts readouts_;
    HeldKeys held_;
    MouseDrag drag_;
    DividerDrag dividerDrag_;
    float step_;       // navigationStep of the scene
    float maxEpsilon_; // the epsilon slider's right end

    // Scenes dropped, opened or restored.
    std::string pendingDrop_;                      // --drop FILE, dropped once the window shows
    std::optional<RenderSettings> pendingRestore_; // a dropped screenshot's, for its scene
    std::optional<Camera> pendingLab_; // its lab camera, when it is of the observer view

    // The tracer's pictures and jobs.
    ShownImage shown_;
    RenderJob submitted_;
    uint64_t submittedSerial_ = 0;
    RenderJob lastView_; // the view of the last picture shown (for stats.viewsShown)
    bool pictureToUpload_ = false;

    // This frame.
    TimePoint wokeAt_;
    InputEvents events_;
    ViewLayout layout_;
    int fbWidth_ = 0, fbHeight_ = 0;
    int drawnWidth_ = 0, drawnHeight_ = 0; // the framebuffer's size at the last frame
    bool meanIndirectWanted_ = false;
    bool inspectWanted_ = false;
    bool observerWanted_ = false;
    int screenshots_ = 0; // screenshots asked for, saved with the next current picture
    bool quit_ = false;
    bool finalFrame_ = false;

    // Frames and timing.
    RedrawSchedule schedule_;
    TimePoint previousFrameTime_;
    RunStats stats_;
    bool wasMinimised_ = false;
    TimePoint minimisedSince_;
    int framesShown_ = 0;
    int exitCode_ = 0;

    // --record and --replay.
    std::optional<SessionRecorder> recorder_;
    std::optional<SessionReplay> replay_;

    // Last: joined first, before anything they call back into goes. Both wake the UI thread
    // (glfwPostEmptyEvent is thread-safe) when they have something to show.
    SceneLoader loader_;
    RenderWorker worker_;
};

} // namespace raylab::viewer
