// The loop, the tracer's pictures, the scene loader, the schedule and the end of a run.

#include "viewer_loop.h"

#include "core/scene_framing.h"
#include "session_state.h"
#include "settings_edit.h"
#include "split_view.h"
#include "viewer_app.h"

#include <algorithm>
#include <cstdio>
#include <glad/gl.h>
#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include "screenshot.h"

#include <GLFW/glfw3.h>

namespace raylab::viewer {

ViewerLoop::ViewerLoop(const CommandLine& command, std::shared_ptr<const LoadedScene> scene,
                       std::optional<SessionRecording> replay)
    : command_(command), flags_(command.viewer), scene_(std::move(scene)),
      scripted_(command.frames > 0),
      needsFinal_(!command.screenshot.empty() || !command.viewer.readback.empty()),
      showPanel_(command.viewer.showPanel), observer_(command.settings, command.observedLabCamera),
      step_(navigationStep(scene_->scene.bounds())),
      maxEpsilon_(100.0f * scaledShadowEpsilon(scene_->scene.bounds())),
      pendingDrop_(command.viewer.drop),
      // Scripted runs and replays draw every frame (N frames take N / 60 s); interactive ones
      // only when wanted.
      schedule_(kFramesPerSecond, command.frames > 0 || replay.has_value()),
      loader_(command.importLimits, [] { glfwPostEmptyEvent(); }),
      worker_(kPreviewBudgetSeconds, [] { glfwPostEmptyEvent(); }) {
    panel_.settings = command.settings;
    panel_.scenePath = scene_->source;
    panel_.resolutionScale = flags_.resolutionScale;
    panel_.split = command.split >= 0.0f;
    panel_.bookmarks = command.bookmarks;
    panel_.divider = panel_.split ? command.split : 0.5f;
    if (replay) {
        replay_.emplace(std::move(*replay));
    }
    if (!flags_.record.empty()) {
        recorder_.emplace();
    }
    stats_.continuous = scripted_;
}

bool ViewerLoop::open(std::string& error) {
    if (!window_.open(command_.settings.width, command_.settings.height,
                      "raylab - " + scene_->source, error)) {
        return false;
    }
    uiScale_ = monitorUiScale();
    // The window was opened at the picture's size: make room for the panel before it shows.
    if (showPanel_) {
        int width = 0, height = 0;
        glfwGetWindowSize(window_.handle(), &width, &height);
        glfwSetWindowSize(window_.handle(), width + scaledPixels(panelUnits_, uiScale_, 1.0f),
                          height);
    }
    window_.show();
    input_.attach(window_.handle()); // before ImGui, whose callbacks chain to these
    gui_.emplace(window_.handle());
    gui_->setScale(uiScale_);
    if (!gui_->ok()) {
        error = "cannot start Dear ImGui";
        return false;
    }
    if (!quad_.create(error) || !panelLayer_.create(error) || !overlayLines_.create(error)) {
        return false;
    }
    keys_.emplace(window_.handle()); // in front of ImGui's key callbacks
    return true;
}

int ViewerLoop::run() {
    previousFrameTime_ = Clock::now();
    minimisedSince_ = previousFrameTime_;
    schedule_.want(previousFrameTime_);
    for (;;) {
        waitForWake();
        pollTracer();
        pollLoader();
        if (!frameDue()) {
            if (quit_ && wasMinimised_) {
                break;
            }
            continue;
        }
        beginFrame();
        handleInput();
        drawFrame();
        if (finalFrame_) {
            break;
        }
        scheduleNextWake();
    }
    return finish();
}

// Sleeps until the schedule's next frame, or less when an event arrives (input, a window event,
// or an empty event posted by the render thread or the scene loader), and processes the events.
// Minimised, nothing is drawn, so frames wanted meanwhile must not end the wait.
void ViewerLoop::waitForWake() {
    const auto idleUntil = after(Clock::now(), kIdleWakeSeconds);
    const auto until = wasMinimised_ ? idleUntil : std::min(schedule_.wakeAt(), idleUntil);
    if (const auto now = Clock::now(); until > now) {
        glfwWaitEventsTimeout(secondsBetween(now, until));
    }
    glfwPollEvents();
    wokeAt_ = Clock::now();
    quit_ = quit_ || glfwWindowShouldClose(window_.handle()) != 0;
}

void ViewerLoop::pollTracer() {
    const bool pictureArrived = worker_.takeLatest(shown_);
    if (pictureArrived) {
        pictureToUpload_ = true;
        schedule_.want(wokeAt_);
    }
    // A picture arriving between frames while a navigation key is held or the mouse drags: the
    // motion up to now becomes the next view at once, so the tracer starts it without waiting
    // for the next frame's slot, and each frame shows the newest view finished.
    if (pictureArrived && (held_.anyHeld() || drag_.dragging()) && submittedSerial_ != 0 &&
        !wasMinimised_ && !schedule_.due(wokeAt_) && !replay_) {
        applyHeldKeys(input_.takeNavKeys());
        if (drag_.dragging()) {
            RenderSettings turned = panel_.settings;
            applyDrag(false, turned);
            std::string ignored;
            acceptEdit(turned, panel_.settings, ignored);
        }
        submitJob();
    }
    if (input_.pending().other) {
        schedule_.want(wokeAt_, kFramesAfterEvent);
    }
    if (input_.pending().keyboard) {
        // Keys that navigate need only the frame that applies them (the picture they change
        // wakes the window again); keys for the panel get ImGui's frames.
        schedule_.want(wokeAt_, ImGui::GetIO().WantCaptureKeyboard ? kFramesAfterEvent : 1);
    }
    // Key events held back for later frames, a held navigation key (it moves the camera or the
    // light every frame) and quitting need the next frame.
    if (keys_->holding() || held_.anyHeld() || quit_) {
        schedule_.want(wokeAt_);
    }
}

void ViewerLoop::pollLoader() {
    auto loaded = loader_.poll();
    if (!loaded) {
        return;
    }
    if (loaded->scene) {
        scene_ = loaded->scene;
        step_ = navigationStep(scene_->scene.bounds());
        maxEpsilon_ = 100.0f * scaledShadowEpsilon(scene_->scene.bounds());
        observer_.leave(panel_.settings); // the new scene places the lab camera
        if (pendingRestore_) {
            panel_.settings = *pendingRestore_; // a dropped screenshot's own settings
            if (pendingLab_) {
                observer_.observe(*pendingLab_, pendingRestore_->camera, panel_.settings);
            }
        } else {
            placeForScene(scene_->scene, isLabBoxName(scene_->source), panel_.settings);
        }
        glfwSetWindowTitle(window_.handle(), ("raylab - " + scene_->source).c_str());
        setStatus("loaded " + scene_->source +
                      (loaded->warnings.empty() ? "" : " (" + loaded->warnings + ")"),
                  false);
    } else {
        setStatus(loaded->error, true);
        if (replay_) { // the recording's scene is gone: the replay cannot go on
            std::fprintf(stderr, "raylab: %s: the replay stops here\n", flags_.replay.c_str());
            exitCode_ = 1;
            quit_ = true;
        }
    }
    pendingRestore_.reset();
    pendingLab_.reset();
    schedule_.want(wokeAt_);
}

bool ViewerLoop::frameDue() {
    window_.framebufferSize(fbWidth_, fbHeight_);
    const bool minimised = window_.minimised();
    if (minimised != wasMinimised_) {
        const auto now = Clock::now();
        if (minimised) {
            minimisedSince_ = now;
        } else {
            stats_.minimisedSeconds += secondsBetween(minimisedSince_, now);
            previousFrameTime_ = now; // the next interval starts now, not before minimising
            schedule_.resume(now);
        }
        wasMinimised_ = minimised;
    }
    if (minimised) {
        return false; // nothing to draw; the tracer keeps its job and stops at the sample cap
    }
    if (fbWidth_ != drawnWidth_ || fbHeight_ != drawnHeight_) {
        schedule_.want(wokeAt_);
    }
    if (!schedule_.due(wokeAt_)) {
        return false;
    }
    schedule_.frameStarted(wokeAt_);
    return true;
}

void ViewerLoop::scheduleNextWake() {
    const auto now = Clock::now();
    // What Dear ImGui needs next: a held button (a drag, a slider) follows the cursor every
    // frame; an active text field blinks its cursor. A held navigation key moves every frame.
    if (ImGui::IsAnyMouseDown() || held_.anyHeld()) {
        schedule_.want(now);
    }
    // The panel ends on the live settings and the last picture's numbers, even when nothing
    // else is drawn then. (A window too narrow for the panel has none: nothing to catch up.)
    if (const auto wake = panelLayer_.nextWake(panel_.settings, numbers_);
        layout_.panelShown() && wake) {
        schedule_.wantAt(*wake);
    }
    // The panel counts a running load's seconds.
    if (layout_.panelShown() && loader_.busy()) {
        schedule_.wantAt(after(now, kLoadClockSeconds));
    }
    if (ImGui::GetIO().WantTextInput) {
        schedule_.wantAt(after(now, kTextCursorSeconds));
    }
}

void ViewerLoop::submitJob() {
    RenderJob job{scene_, panel_.settings, true};
    if (replay_) {
        if (replay_->state().scene != scene_->source) {
            return; // its scene is loading
        }
        job = recordedJob(replay_->state(), scene_, replay_->pendingScreenshot());
    } else if (panel_.split) {
        const RenderSettings* snapshot =
            panel_.compareSnapshot && panel_.snapshot ? &*panel_.snapshot : nullptr;
        job.compare = splitCompare(panel_.settings, snapshot);
        // Holding F flips to the right side (A) over the whole picture, in either mode.
        const bool flip = glfwGetKey(window_.handle(), GLFW_KEY_F) == GLFW_PRESS;
        job.divider = flip ? 0.0f : panel_.divider;
        job.compareMode = flip ? CompareMode::Wipe : panel_.compareMode;
        job.differenceScale = panel_.differenceScale;
    }
    // Every picture comes with its linear picture: the panel reads the pixel under the cursor
    // and a rectangle's mean from it, F12 writes it (.exr) beside the PNG, and PFM and EXR
    // screenshots are written from it.
    if (submittedSerial_ == 0 || !sameJob(job, submitted_) ||
        job.keepLinear != submitted_.keepLinear) {
        submittedSerial_ = worker_.submit(job);
        submitted_ = job;
    }
    if (recorder_) {
        recorder_->note(framesShown_, recordedState(job, panel_.inspected,
                                                    observer_.keptLabCamera(), panel_.bookmarks));
    }
}

void ViewerLoop::cancelLoad() {
    if (const auto running = loader_.progress(); running && loader_.cancel()) {
        pendingRestore_.reset();
        setStatus("cancelled loading " + running->source, false);
    }
}

void ViewerLoop::setStatus(const std::string& text, bool isError) {
    panel_.status = text;
    panel_.statusIsError = isError;
    std::fprintf(stderr, "raylab: %s\n", text.c_str());
}

float ViewerLoop::monitorUiScale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window_.handle(), &x, &y);
    return flags_.uiScale > 0.0f ? flags_.uiScale
                                 : uiScaleFor(std::max(x, y), window_.framebufferScale());
}

void ViewerLoop::sizeWindowFor(int width, int height) {
    const float perPixel = 1.0f / window_.framebufferScale();
    const int column = showPanel_ ? scaledPixels(panelUnits_, uiScale_, 1.0f) : 0;
    glfwSetWindowSize(window_.handle(),
                      scaledPixels(static_cast<float>(width), 1.0f, perPixel) + column,
                      scaledPixels(static_cast<float>(height), 1.0f, perPixel));
}

ViewLayout ViewerLoop::layoutOf(int framebufferWidth, int framebufferHeight) const {
    const float f = window_.framebufferScale();
    return viewLayout(framebufferWidth, framebufferHeight, showPanel_,
                      scaledPixels(panelUnits_, uiScale_, f),
                      scaledPixels(kMinPanelColumnWidth, uiScale_, f));
}

int ViewerLoop::finish() {
    std::string error;
    if (wasMinimised_) {
        stats_.minimisedSeconds += secondsBetween(minimisedSince_, Clock::now());
    }
    if (!flags_.stats.empty()) {
        stats_.tracer = worker_.totals();
        stats_.width = shown_.bgra.width;
        stats_.height = shown_.bgra.height;
        stats_.samples = shown_.preview ? 0 : shown_.settings.samplesPerPixel;
        stats_.scene = scene_->source;
        stats_.triangles = scene_->scene.triangles.size();
        stats_.hover = readouts_.hover();
        stats_.rectangle = readouts_.rectangleMean();
        if (!writeRunStats(flags_.stats, stats_, error)) {
            std::fprintf(stderr, "raylab: %s\n", error.c_str());
            exitCode_ = 1;
        }
    }
    if (!command_.screenshot.empty()) {
        if (shown_.bgra.width > 0 && !shown_.preview) {
            if (!saveScreenshot(command_.screenshot, shown_, error,
                                {panel_.bookmarks, observer_.keptLabCamera()})) {
                std::fprintf(stderr, "raylab: %s\n", error.c_str());
                exitCode_ = 1;
            }
        } else {
            std::fprintf(stderr, "raylab: %s not written: no finished picture was shown\n",
                         command_.screenshot.c_str());
            exitCode_ = 1;
        }
    }
    if (recorder_ && !recorder_->save(flags_.record, framesShown_, error)) {
        std::fprintf(stderr, "raylab: %s\n", error.c_str());
        exitCode_ = 1;
    }
    if (replay_ && !replay_->finished() && exitCode_ == 0) {
        std::fprintf(stderr, "raylab: %s: the replay was stopped at frame %ld of %ld\n",
                     flags_.replay.c_str(), replay_->frame(), replay_->frames());
    }
    return exitCode_;
}

int runViewer(const CommandLine& command, std::shared_ptr<const LoadedScene> scene,
              std::optional<SessionRecording> replay) {
    ViewerLoop loop(command, std::move(scene), std::move(replay));
    std::string error;
    if (!loop.open(error)) {
        std::fprintf(stderr, "raylab: %s\n", error.c_str());
        return 1;
    }
    return loop.run();
}

} // namespace raylab::viewer
