#include "viewer_app.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glad/gl.h>
#include <imgui.h>
#include <string>

#define GLFW_INCLUDE_NONE
#include "core/integrators/pixel_inspection.h"
#include "core/scene_framing.h"
#include "gl_overlay.h"
#include "gl_window.h"
#include "held_keys.h"
#include "image_quad.h"
#include "input.h"
#include "io/inspection_json.h"
#include "key_list.h"
#include "key_relay.h"
#include "observer_geometry.h"
#include "observer_view.h"
#include "orbit_controls.h"
#include "panel.h"
#include "panel_context.h"
#include "panel_layer.h"
#include "picture_readouts.h"
#include "ray_overlay_geometry.h"
#include "redraw_schedule.h"
#include "render_worker.h"
#include "run_stats.h"
#include "scene_loader.h"
#include "screenshot.h"
#include "settings_edit.h"
#include "settings_history.h"
#include "split_view.h"
#include "view_layout.h"

#include <GLFW/glfw3.h>

namespace raylab::viewer {

namespace {

using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

// Sleeps until `until`, or less when an event arrives (input, a window event, or an empty event
// posted by the render thread or the scene loader), and processes the events.
void waitForEvents(Clock::time_point until) {
    const auto now = Clock::now();
    if (until > now) {
        glfwWaitEventsTimeout(secondsBetween(now, until));
    }
    glfwPollEvents();
}

bool isLabBox(const LoadedScene& scene) { return isLabBoxName(scene.source); }

// Clears to black what the picture does not cover: the panel's column (the panel's cache draws
// only the pixels the panel covers), and before the first picture the whole framebuffer.
void clearUncovered(const ViewLayout& layout, bool pictureDrawn) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    if (!pictureDrawn) {
        glDisable(GL_SCISSOR_TEST);
        glClear(GL_COLOR_BUFFER_BIT);
    } else if (layout.panelShown()) {
        const GlBox column = glBox(layout.panel, layout.framebufferHeight);
        glEnable(GL_SCISSOR_TEST);
        glScissor(column.x, column.y, column.width, column.height);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
    }
}

// Render resolution for a side of the picture's box: side * scale, at least 1 and at most the
// maximum.
int renderSide(int pictureSide, float scale) {
    const long side = std::lround(static_cast<double>(pictureSide) * scale);
    return static_cast<int>(std::clamp(side, 1L, static_cast<long>(kMaxImageSide)));
}

// The navigation keys' presses and releases of this frame, handed to `held`. Presses while ImGui
// wants the keyboard are its own; then no key stays held either.
void trackHeldKeys(const std::vector<NavKeyChange>& changes, bool panelHasKeyboard,
                   Clock::time_point now, HeldKeys& held) {
    for (const NavKeyChange& change : changes) {
        switch (change.kind) {
        case NavKeyChange::Kind::Press:
            if (!panelHasKeyboard) {
                held.press(change.action, change.when);
            }
            break;
        case NavKeyChange::Kind::Release: held.release(change.action, change.when); break;
        case NavKeyChange::Kind::FocusLost: held.releaseAll(change.when); break;
        }
    }
    if (panelHasKeyboard) {
        held.releaseAll(now);
    }
}

// The navigation keys' changes, then the held keys' motion up to `now`, applied to `settings`
// (the motion as a whole is refused when it would make them invalid).
void applyHeldKeys(const std::vector<NavKeyChange>& changes, bool panelHasKeyboard,
                   Clock::time_point now, float step, HeldKeys& held, RenderSettings& settings) {
    trackHeldKeys(changes, panelHasKeyboard, now, held);
    RenderSettings next = settings;
    for (const NavMotion& motion : held.advance(now)) {
        applyNavAction(motion.action, step, next, motion.steps);
    }
    std::string ignored;
    acceptEdit(next, settings, ignored);
}

// The mouse drag's turn since its last update applied to `settings`; `start`: a press outside
// the panel happened now. The picture is pictureHeight framebuffer pixels high.
void applyDrag(GLFWwindow* window, MouseDrag& drag, bool start, int pictureHeight,
               RenderSettings& settings) {
    float yaw = 0.0f, pitch = 0.0f;
    drag.update(window, start,
                settings.camera.verticalFovDegrees / static_cast<float>(std::max(pictureHeight, 1)),
                yaw, pitch);
    if (yaw != 0.0f || pitch != 0.0f) {
        turnCamera(yaw, pitch, settings);
    }
}

// Keys, wheel and drag of this frame (at `now`) applied to the settings (those ImGui wants go to
// ImGui). Navigation keys move by a step per press and smoothly while held (held_keys.h). The
// picture is shown over the framebuffer's box `picture` (view_layout.h).
void applyInput(const InputEvents& events, Clock::time_point now, GLFWwindow* window, float step,
                const PixelBox& picture, HeldKeys& held, MouseDrag& drag, DividerDrag& dividerDrag,
                PanelState& panel, bool& showPanel, int& screenshots, bool& meanIndirectWanted,
                bool& inspectWanted, bool& showKeys, bool& observerWanted, SettingsHistory& history,
                const LoadedScene& scene, OrbitControls& orbit, bool& quit) {
    const ImGuiIO& io = ImGui::GetIO();
    applyHeldKeys(events.navKeys, io.WantCaptureKeyboard, now, step, held, panel.settings);
    RenderSettings next = panel.settings;
    for (const int key : events.keys) {
        if (const auto slot = bookmarkForKey(key); slot && !io.WantCaptureKeyboard) {
            const bool ctrl = glfwGetKey(window, GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS ||
                              glfwGetKey(window, GLFW_KEY_RIGHT_CONTROL) == GLFW_PRESS;
            std::optional<Camera>& bookmark =
                panel.bookmarks.slots[static_cast<std::size_t>(*slot)];
            if (ctrl) {
                bookmark = next.camera;
            } else if (bookmark) {
                next.camera = *bookmark;
            }
        }
        if (const auto command = commandForKey(key)) {
            if (*command == Command::Screenshot) {
                ++screenshots;
            } else if (*command == Command::TogglePanel) {
                showPanel = !showPanel;
            } else if (io.WantCaptureKeyboard) {
                // typed into the panel
            } else if (*command == Command::UseMeanIndirect) {
                meanIndirectWanted = true;
            } else if (*command == Command::ToggleSplit) {
                panel.split = !panel.split;
            } else if (*command == Command::NextCompareMode) {
                // The difference needs two sides: it turns the split on.
                panel.compareMode = panel.compareMode == CompareMode::Wipe ? CompareMode::Difference
                                                                           : CompareMode::Wipe;
                panel.split = panel.split || panel.compareMode == CompareMode::Difference;
            } else if (*command == Command::Undo || *command == Command::Redo) {
                const auto down = [window](int a, int b) {
                    return glfwGetKey(window, a) == GLFW_PRESS ||
                           glfwGetKey(window, b) == GLFW_PRESS;
                };
                if (down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL)) {
                    const bool redo = *command == Command::Redo ||
                                      down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
                    if (redo ? history.redo(next) : history.undo(next)) {
                        panel.settings = next;
                    }
                }
            } else if (*command == Command::ToggleObserver) {
                observerWanted = true;
            } else if (*command == Command::ToggleKeyList) {
                showKeys = !showKeys;
            } else if (*command == Command::KeepSnapshot) {
                panel.snapshot = next;
                panel.compareSnapshot = true;
                panel.split = true;
            } else if (*command == Command::NextView) {
                const bool shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                                   glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
                next.view = nextView(next.view, shift ? -1 : 1);
            } else {
                quit = true;
            }
        }
    }
    if (!io.WantCaptureMouse && events.scroll != 0.0) {
        moveCamera(static_cast<float>(events.scroll) * step, next);
    }
    if (events.inspectPressed && !io.WantCaptureMouse) {
        double x = 0.0, y = 0.0;
        cursorInPixels(window, x, y);
        int px = 0, py = 0;
        if (pixelUnderCursor(x, y, picture, panel.settings.width, panel.settings.height, px, py)) {
            panel.inspected = InspectedPixel{px, py, panel.settings.camera, panel.settings.width,
                                             panel.settings.height};
            inspectWanted = true;
        }
    }
    applyOrbitAndPan(events, io.WantCaptureMouse, window, scene, picture, orbit, next);
    const bool press = events.leftPressed && !io.WantCaptureMouse;
    const bool onDivider = panel.split && panel.compareMode == CompareMode::Wipe &&
                           dividerDrag.update(window, press, picture, panel.divider);
    applyDrag(window, drag, press && !onDivider, picture.height, next);
    std::string ignored;
    acceptEdit(next, panel.settings, ignored);
}

// What the panel says about a picture of the tracer.
PictureFacts pictureFacts(const ShownImage& shown) {
    PictureFacts facts;
    facts.width = shown.bgra.width;
    facts.height = shown.bgra.height;
    facts.samples = shown.preview ? 0 : shown.settings.samplesPerPixel;
    facts.preview = shown.preview;
    facts.final = shown.final;
    facts.passMs = shown.passSeconds * 1000.0;
    facts.raysPerSecond = shown.raysPerSecond;
    if (!shown.preview && shown.passSeconds > 0.0) {
        facts.samplesPerSecond = static_cast<double>(shown.bgra.width) *
                                 static_cast<double>(shown.bgra.height) / shown.passSeconds;
    }
    facts.noisePercent = shown.noise.known ? 100.0 * shown.noise.relativeError : -1.0;
    // A split picture's path-traced side is the left one unless only the right is path traced.
    const RenderSettings& pathSide = shown.compare &&
                                             shown.compare->integrator == Integrator::Path &&
                                             shown.settings.integrator != Integrator::Path
                                         ? *shown.compare
                                         : shown.settings;
    facts.pathTraced = !shown.preview && pathSide.integrator == Integrator::Path &&
                       pathSide.view == View::Beauty && pathSide.samplesPerPixel > 0;
    facts.meanIndirect = facts.pathTraced ? shown.meanIndirect : glm::vec3(0.0f);
    return facts;
}

// "The lab's N for this scene": the constant indirect term set to the path-traced picture's mean
// N, which a person can then compare with the computed light. False when no such mean is known.
bool useMeanIndirect(const PictureFacts& picture, RenderSettings& settings) {
    if (!picture.pathTraced) {
        return false;
    }
    RenderSettings next = settings;
    next.indirect = true;
    splitColourIntensity(picture.meanIndirect, next.indirectColor, next.indirectIntensity);
    std::string ignored;
    return acceptEdit(next, settings, ignored);
}

void setStatus(PanelState& panel, const std::string& text, bool isError) {
    panel.status = text;
    panel.statusIsError = isError;
    std::fprintf(stderr, "raylab: %s\n", text.c_str());
}

} // namespace

int runViewer(const CommandLine& command, std::shared_ptr<const LoadedScene> scene) {
    const ViewerFlags& flags = command.viewer; // the viewer's own options
    GlWindow window;
    std::string error;
    if (!window.open(command.settings.width, command.settings.height, "raylab - " + scene->source,
                     error)) {
        std::fprintf(stderr, "raylab: %s\n", error.c_str());
        return 1;
    }
    bool showPanel = flags.showPanel;
    // The panel's scale (--ui-scale, else the window's content scale per framebuffer scale) and
    // its column's width at scale 1 (a drag of its edge changes it).
    const auto monitorUiScale = [&] {
        float x = 1.0f, y = 1.0f;
        glfwGetWindowContentScale(window.handle(), &x, &y);
        return flags.uiScale > 0.0f ? flags.uiScale
                                    : uiScaleFor(std::max(x, y), window.framebufferScale());
    };
    float uiScale = monitorUiScale();
    float panelUnits = kPanelColumnWidth;
    // The window's size (screen coordinates) that shows a picture of width x height pixels with
    // the panel's column, when shown, beside it.
    const auto sizeWindowFor = [&](int width, int height) {
        const float perPixel = 1.0f / window.framebufferScale();
        const int column = showPanel ? scaledPixels(panelUnits, uiScale, 1.0f) : 0;
        glfwSetWindowSize(window.handle(),
                          scaledPixels(static_cast<float>(width), 1.0f, perPixel) + column,
                          scaledPixels(static_cast<float>(height), 1.0f, perPixel));
    };
    // The window was opened at the picture's size: make room for the panel before it shows.
    if (showPanel) {
        int width = 0, height = 0;
        glfwGetWindowSize(window.handle(), &width, &height);
        glfwSetWindowSize(window.handle(), width + scaledPixels(panelUnits, uiScale, 1.0f), height);
    }
    window.show();
    // This frame's layout (view_layout.h): the panel's column and the picture's box.
    const auto layoutOf = [&](int framebufferWidth, int framebufferHeight) {
        const float f = window.framebufferScale();
        return viewLayout(framebufferWidth, framebufferHeight, showPanel,
                          scaledPixels(panelUnits, uiScale, f),
                          scaledPixels(kMinPanelColumnWidth, uiScale, f));
    };
    InputCollector input;
    input.attach(window.handle()); // before ImGui, whose callbacks chain to these
    PanelContext gui(window.handle());
    gui.setScale(uiScale);
    ImageQuad quad;
    PanelLayer panelLayer; // the panel drawn, its cached pixels, the copies of numbers it shows
    OverlayLines overlayLines;
    if (!gui.ok() || !quad.create(error) || !panelLayer.create(error) ||
        !overlayLines.create(error)) {
        std::fprintf(stderr, "raylab: %s\n", gui.ok() ? error.c_str() : "cannot start Dear ImGui");
        return 1;
    }
    KeyRelay keys(window.handle()); // in front of ImGui's key callbacks
    // Both wake the UI thread when they have something to show (glfwPostEmptyEvent is
    // thread-safe); both are joined before the window closes.
    SceneLoader loader(command.importLimits, [] { glfwPostEmptyEvent(); });
    RenderWorker worker(kPreviewBudgetSeconds, [] { glfwPostEmptyEvent(); }); // last: joined first

    PanelState panel;
    panel.settings = command.settings;
    panel.scenePath = scene->source;
    panel.resolutionScale = flags.resolutionScale;
    panel.split = command.split >= 0.0f;
    panel.bookmarks = command.bookmarks;
    panel.divider = panel.split ? command.split : 0.5f;
    bool showKeys = false; // the list of keys and mouse gestures (H)
    // The observer view (O) and the undo and redo (Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y) of the camera
    // being moved.
    ObserverView observer(panel.settings, command.observedLabCamera);
    OrbitControls orbit;      // right drag orbits, middle drag pans
    PictureReadouts readouts; // the pixel under the cursor, a Shift + drag rectangle's mean
    std::string pendingDrop = flags.drop;         // --drop FILE, dropped once the window shows
    std::optional<RenderSettings> pendingRestore; // a dropped screenshot's, for its scene
    std::optional<Camera> pendingLab;             // its lab camera, when it is of the observer view
    float step = navigationStep(scene->scene.bounds());
    float maxEpsilon = 100.0f * scaledShadowEpsilon(scene->scene.bounds());

    HeldKeys held;      // the navigation keys held down
    RenderJob lastView; // the view of the last picture shown (for stats.viewsShown)
    MouseDrag drag;
    DividerDrag dividerDrag;
    ShownImage shown;
    RenderJob submitted;
    uint64_t submittedSerial = 0;
    PanelNumbers numbers; // live: every frame and picture
    int framesShown = 0;
    int screenshots = 0;
    bool quit = false;
    int exitCode = 0;
    const bool scripted = command.frames > 0;
    const bool needsFinal = !command.screenshot.empty() || !flags.readback.empty();
    // Hands the panel's settings to the render thread when they make another job than the last.
    // Every picture comes with its linear picture: the panel reads the pixel under the cursor and
    // a rectangle's mean from it, F12 writes it (.exr) beside the PNG, and PFM and EXR
    // screenshots are written from it.
    const auto submitSettings = [&] {
        RenderJob job{scene, panel.settings, true};
        if (panel.split) {
            const RenderSettings* snapshot =
                panel.compareSnapshot && panel.snapshot ? &*panel.snapshot : nullptr;
            job.compare = splitCompare(panel.settings, snapshot);
            // Holding F flips to the right side (A) over the whole picture, in either mode.
            const bool flip = glfwGetKey(window.handle(), GLFW_KEY_F) == GLFW_PRESS;
            job.divider = flip ? 0.0f : panel.divider;
            job.compareMode = flip ? CompareMode::Wipe : panel.compareMode;
            job.differenceScale = panel.differenceScale;
        }
        if (submittedSerial == 0 || !sameJob(job, submitted) ||
            job.keepLinear != submitted.keepLinear) {
            submittedSerial = worker.submit(job);
            submitted = job;
        }
    };
    // Kills the running load's helper; the scene, camera, samples and settings stay.
    const auto cancelLoad = [&] {
        if (const auto running = loader.progress(); running && loader.cancel()) {
            pendingRestore.reset();
            setStatus(panel, "cancelled loading " + running->source, false);
        }
    };
    // Scripted runs draw every frame (N frames take N / 60 s); interactive ones only when wanted.
    RedrawSchedule schedule(kFramesPerSecond, scripted);
    auto previousFrameTime = Clock::now();
    schedule.want(previousFrameTime);
    RunStats stats;
    stats.continuous = scripted;
    bool wasMinimised = false;
    auto minimisedSince = previousFrameTime;
    bool pictureToUpload = false;        // shown holds a picture not uploaded yet
    int drawnWidth = 0, drawnHeight = 0; // the framebuffer's size at the last frame
    ViewLayout layout;                   // the panel's column and the picture's box, this frame

    for (;;) {
        // Minimised, nothing is drawn, so frames wanted meanwhile must not end the wait.
        const auto idleUntil = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(kIdleWakeSeconds));
        waitForEvents(wasMinimised ? idleUntil : std::min(schedule.wakeAt(), idleUntil));
        const auto wokeAt = Clock::now();
        quit = quit || glfwWindowShouldClose(window.handle()) != 0;
        const bool pictureArrived = worker.takeLatest(shown);
        if (pictureArrived) {
            pictureToUpload = true;
            schedule.want(wokeAt);
        }
        // A picture arriving between frames while a navigation key is held or the mouse drags:
        // the motion up to now becomes the next view at once, so the tracer starts it without
        // waiting for the next frame's slot, and each frame shows the newest view finished.
        if (pictureArrived && (held.anyHeld() || drag.dragging()) && submittedSerial != 0 &&
            !wasMinimised && !schedule.due(wokeAt)) {
            applyHeldKeys(input.takeNavKeys(), ImGui::GetIO().WantCaptureKeyboard, wokeAt, step,
                          held, panel.settings);
            if (drag.dragging()) {
                RenderSettings turned = panel.settings;
                applyDrag(window.handle(), drag, false, layout.picture.height, turned);
                std::string ignored;
                acceptEdit(turned, panel.settings, ignored);
            }
            submitSettings();
        }
        if (input.pending().other) {
            schedule.want(wokeAt, kFramesAfterEvent);
        }
        if (input.pending().keyboard) {
            // Keys that navigate need only the frame that applies them (the picture they
            // change wakes the window again); keys for the panel get ImGui's frames.
            schedule.want(wokeAt, ImGui::GetIO().WantCaptureKeyboard ? kFramesAfterEvent : 1);
        }
        // Key events held back for later frames, a held navigation key (it moves the camera or
        // the light every frame) and quitting need the next frame.
        if (keys.holding() || held.anyHeld() || quit) {
            schedule.want(wokeAt);
        }

        if (auto loaded = loader.poll()) {
            if (loaded->scene) {
                scene = loaded->scene;
                step = navigationStep(scene->scene.bounds());
                maxEpsilon = 100.0f * scaledShadowEpsilon(scene->scene.bounds());
                observer.leave(panel.settings); // the new scene places the lab camera
                if (pendingRestore) {
                    panel.settings = *pendingRestore; // a dropped screenshot's own settings
                    if (pendingLab) {
                        observer.observe(*pendingLab, pendingRestore->camera, panel.settings);
                    }
                } else {
                    placeForScene(scene->scene, isLabBox(*scene), panel.settings);
                }
                glfwSetWindowTitle(window.handle(), ("raylab - " + scene->source).c_str());
                setStatus(panel,
                          "loaded " + scene->source +
                              (loaded->warnings.empty() ? "" : " (" + loaded->warnings + ")"),
                          false);
            } else {
                setStatus(panel, loaded->error, true);
            }
            pendingRestore.reset();
            pendingLab.reset();
            schedule.want(wokeAt);
        }

        int fbWidth = 0, fbHeight = 0;
        window.framebufferSize(fbWidth, fbHeight);
        const bool minimised = window.minimised();
        if (minimised != wasMinimised) {
            const auto now = Clock::now();
            if (minimised) {
                minimisedSince = now;
            } else {
                stats.minimisedSeconds +=
                    std::chrono::duration<double>(now - minimisedSince).count();
                previousFrameTime = now; // the next interval starts now, not before minimising
                schedule.resume(now);
            }
            wasMinimised = minimised;
        }
        if (minimised) {
            if (quit) {
                break;
            }
            continue; // nothing to draw; the tracer keeps its job and stops at the sample cap
        }
        if (fbWidth != drawnWidth || fbHeight != drawnHeight) {
            schedule.want(wokeAt);
        }
        if (!schedule.due(wokeAt)) {
            continue;
        }
        schedule.frameStarted(wokeAt);

        // Another monitor's content scale: the panel's font and sizes follow (not --ui-scale's).
        if (input.pending().contentScale) {
            uiScale = monitorUiScale();
            gui.setScale(uiScale);
        }
        layout = layoutOf(fbWidth, fbHeight);
        gui.beginFrame();
        if (pictureToUpload) {
            quad.upload(shown.bgra);
            stats.uploads.add(quad.lastUploadSeconds());
            RenderJob view{shown.scene, shown.settings};
            view.settings.width = shown.bgra.width; // a preview's view at its shown size
            view.settings.height = shown.bgra.height;
            if (!samePicture(view, lastView)) {
                ++stats.viewsShown;
                lastView = view;
            }
            if (shown.passSeconds > 0.0) {
                numbers.passMs.push(static_cast<float>(shown.passSeconds * 1000.0));
            }
            numbers.uploadMs = quad.lastUploadSeconds() * 1000.0;
            numbers.picture = pictureFacts(shown);
            if (numbers.picture.noisePercent >= 0.0) {
                numbers.noisePercent.push(static_cast<float>(numbers.picture.noisePercent));
            }
            pictureToUpload = false;
        }
        bool meanIndirectWanted = false;
        bool inspectWanted = false;
        bool observerWanted = false; // O or the panel's checkbox
        InputEvents events = input.take();
        if (!pendingDrop.empty() && framesShown > 0) {
            events.dropped.push_back(pendingDrop); // --drop: as if dropped once the window shows
            pendingDrop.clear();
        }
        // A dropped mesh opens; a dropped screenshot (.png or .json) restores its scene, settings,
        // size and bookmarks.
        for (const std::string& path : events.dropped) {
            if (!isScreenshotPath(path)) {
                panel.scenePath = path;
                loader.start(path); // replaces a running load
                pendingRestore.reset();
                continue;
            }
            RenderSettings restored;
            SettingsJsonExtras extras;
            std::string why;
            if (!readScreenshotSettings(path, restored, extras, why)) {
                setStatus(panel, why, true);
                continue;
            }
            panel.bookmarks = extras.bookmarks;
            panel.resolutionScale = 1.0f;
            sizeWindowFor(restored.width, restored.height);
            const std::string restoredScene = extras.scene.empty() ? scene->source : extras.scene;
            if (restoredScene == scene->source) {
                observer.leave(panel.settings);
                panel.settings = restored;
                if (extras.observedLabCamera) { // the observer's picture, the lab camera kept
                    observer.observe(*extras.observedLabCamera, restored.camera, panel.settings);
                }
            } else {
                loader.start(restoredScene);
                pendingRestore = restored; // applied when the scene has loaded
                pendingLab = extras.observedLabCamera;
                panel.scenePath = restoredScene;
            }
            setStatus(panel, "restored " + path, false);
        }
        // Escape cancels a running load (even while the panel has the keyboard) instead of
        // quitting.
        if (const auto escape = std::find(events.keys.begin(), events.keys.end(), GLFW_KEY_ESCAPE);
            escape != events.keys.end() && loader.busy()) {
            events.keys.erase(escape);
            cancelLoad();
        }
        applyInput(events, wokeAt, window.handle(), step, layout.picture, held, drag, dividerDrag,
                   panel, showPanel, screenshots, meanIndirectWanted, inspectWanted, showKeys,
                   observerWanted, observer.history(), *scene, orbit, quit);
        readouts.update(window.handle(), events, ImGui::GetIO().WantCaptureMouse, layout.picture,
                        shown);
        // The inspected pixel's numbers, for the panel (a few rays, on this thread); printed as
        // JSON (raylab-render --inspect's) on standard output when a click asks, for scripts.
        std::optional<PixelInspection> inspection;
        if (panel.inspected) {
            inspection = inspectPixel(scene->scene, scene->bvh, scene->emitters,
                                      inspectionSettings(panel.settings, *panel.inspected),
                                      panel.inspected->x, panel.inspected->y);
            if (inspectWanted) {
                std::printf("%s\n", inspectionToJson(*inspection).c_str());
                std::fflush(stdout);
            }
        }
        if (layout.panelShown()) { // F1 hides it; a window too narrow for it has none
            PanelView view;
            const float perUnit = window.framebufferScale(); // framebuffer pixels per unit
            view.width = static_cast<float>(layout.panel.width) / perUnit;
            view.minWidth = kMinPanelColumnWidth * uiScale;
            view.maxWidth = static_cast<float>(fbWidth - 1) / perUnit; // a pixel of picture
            view.sceneName = scene->source;
            view.triangles = scene->scene.triangles.size();
            view.loading = loader.progress();
            view.step = step;
            view.maxEpsilon = maxEpsilon;
            view.hasEmitters = !scene->emitters.empty();
            view.observer = observer.on();
            view.inspection = inspection ? &*inspection : nullptr;
            view.hover = readouts.hover() ? &*readouts.hover() : nullptr;
            view.rectangle = readouts.rectangleMean() ? &*readouts.rectangleMean() : nullptr;
            const ImGuiIO& io = ImGui::GetIO();
            const PanelActions actions =
                panelLayer.draw(panel, std::move(view), numbers,
                                io.WantCaptureMouse || io.WantCaptureKeyboard, wokeAt);
            if (actions.resizedTo > 0.0f) { // its edge dragged: the picture gets the rest
                panelUnits = actions.resizedTo / uiScale;
                layout = layoutOf(fbWidth, fbHeight);
            }
            screenshots += actions.screenshot ? 1 : 0;
            if (actions.frameScene) {
                frameScene(scene->scene, panel.settings);
            }
            if (actions.resetToLab) {
                observer.leave(panel.settings); // the lab's defaults are the lab camera's
                resetToLabDefaults(scene->scene, isLabBox(*scene), panel.settings);
            }
            if (actions.openScene) {
                loader.start(panel.scenePath); // replaces a running load
                pendingRestore.reset();
            }
            if (actions.cancelLoad) {
                cancelLoad();
            }
            meanIndirectWanted = meanIndirectWanted || actions.useMeanIndirect;
            observerWanted = observerWanted || actions.toggleObserver;
            if (actions.keepSnapshot) {
                panel.snapshot = panel.settings;
                panel.compareSnapshot = true;
                panel.split = true;
            }
        }
        if (observerWanted) {
            observer.toggle(panel.settings, scene->scene.bounds());
        }
        if (meanIndirectWanted) {
            if (useMeanIndirect(numbers.picture, panel.settings)) {
                const glm::vec3 n = panel.settings.indirect3();
                char text[96];
                std::snprintf(
                    text, sizeof text, "the lab's N set to the mean path-traced N, %.3f %.3f %.3f",
                    static_cast<double>(n.x), static_cast<double>(n.y), static_cast<double>(n.z));
                setStatus(panel, text, false);
            } else {
                setStatus(panel, "no path-traced picture yet: its mean N is not known", true);
            }
        }

        // The job: the panel's settings at the picture box's resolution times the scale.
        panel.settings.width = renderSide(layout.picture.width, panel.resolutionScale);
        panel.settings.height = renderSide(layout.picture.height, panel.resolutionScale);
        observer.history().observe(panel.settings, wokeAt);
        submitSettings();
        // A picture of the current job that settings reproduce exactly.
        const bool current =
            shown.jobSerial == submittedSerial && !shown.preview && shown.bgra.width > 0;
        const bool scriptEnds = scripted && framesShown + 1 >= command.frames &&
                                (!needsFinal || (current && shown.final));
        const bool finalFrame = quit || scriptEnds;

        // The picture, when there is one, covers every pixel of its box.
        clearUncovered(layout, quad.hasImage());
        quad.draw(layout);
        if (shown.compare && shown.compareMode == CompareMode::Wipe) {
            drawDivider(layout, splitColumn(layout.picture.width, shown.divider));
        }
        if (const auto lab = observer.keptLabCamera(); lab && shown.bgra.width > 0) {
            // The lab camera and the light, seen with the camera of the picture shown (the
            // observer's), over it.
            overlayLines.draw(observerOverlay(shown.settings.camera, shown.bgra.width,
                                              shown.bgra.height, *lab, panel.settings.width,
                                              panel.settings.height, panel.settings.light,
                                              scene->scene.bounds(), kNearDepthPerStep * step),
                              shown.bgra.width, shown.bgra.height, layout);
        }
        if (inspection && shown.bgra.width > 0 && shown.bgra.height > 0) {
            // Its rays, pinned in the world, seen with the camera of the picture shown (so they
            // move with the picture); the marker while that picture is the one it was picked in.
            RenderSettings picture = shown.settings;
            picture.width = shown.bgra.width;
            picture.height = shown.bgra.height;
            const std::vector<ImageSegment> rays =
                projectSegments(PrimaryRays(picture.camera, picture.width, picture.height),
                                picture.width, picture.height, kNearDepthPerStep * step,
                                inspectionSegments(*inspection, panel.inspected->camera.position));
            overlayLines.draw(rays, picture.width, picture.height, layout);
            if (seenAsPicked(picture, *panel.inspected)) {
                drawPixelMarker(layout, panel.inspected->x, panel.inspected->y, picture.width,
                                picture.height);
            }
        }
        if (const auto& r = readouts.rectangle()) {
            drawPixelRectangle(layout, r->x0, r->y0, r->x1, r->y1, shown.bgra.width,
                               shown.bgra.height);
        }
        if (screenshots > 0 && current && !shown.linear.pixels.empty()) {
            std::string path;
            if (saveNumberedScreenshot(command.screenshotDir, shown, path, error,
                                       {panel.bookmarks, observer.keptLabCamera()})) {
                setStatus(panel, "saved " + path, false);
            } else {
                setStatus(panel, "screenshot not saved: " + error, true);
            }
            screenshots = 0;
        }
        if (showKeys) { // centred on the picture
            const float perUnit = window.framebufferScale();
            drawKeyList((static_cast<float>(layout.picture.x) +
                         0.5f * static_cast<float>(layout.picture.width)) /
                            perUnit,
                        (static_cast<float>(layout.picture.y) +
                         0.5f * static_cast<float>(layout.picture.height)) /
                            perUnit);
        }
        panelLayer.composite(gui.endFrame(), fbWidth, fbHeight);
        keys.frameEnded();
        if (finalFrame && !flags.readback.empty()) {
            if (!writePng(flags.readback, readFramebuffer(fbWidth, fbHeight), error)) {
                std::fprintf(stderr, "raylab: %s\n", error.c_str());
                exitCode = 1;
            }
        }
        glfwSwapBuffers(window.handle());
        ++framesShown;
        drawnWidth = fbWidth;
        drawnHeight = fbHeight;
        const auto now = Clock::now();
        const double interval = secondsBetween(previousFrameTime, now);
        const double response = schedule.frameShown(now);
        numbers.frameMs.push(static_cast<float>(interval * 1000.0));
        numbers.drawMs.push(static_cast<float>(secondsBetween(wokeAt, now) * 1000.0));
        stats.drawTimes.add(secondsBetween(wokeAt, now));
        previousFrameTime = now;
        if (stats.framesShown++ > 0) { // the first swap starts the clock
            stats.frameResponses.add(response);
            stats.shownSeconds += interval;
            stats.slowFrames += response > 1.0 / 30.0 ? 1 : 0;
        }
        if (finalFrame) {
            break;
        }
        // What Dear ImGui needs next: a held button (a drag, a slider) follows the cursor every
        // frame; an active text field blinks its cursor. A held navigation key moves every frame.
        if (ImGui::IsAnyMouseDown() || held.anyHeld()) {
            schedule.want(now);
        }
        // The panel ends on the live settings and the last picture's numbers, even when nothing
        // else is drawn then.
        if (const auto wake = panelLayer.nextWake(panel.settings, numbers); showPanel && wake) {
            schedule.wantAt(*wake);
        }
        // The panel counts a running load's seconds.
        if (showPanel && loader.busy()) {
            schedule.wantAt(now + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(kLoadClockSeconds)));
        }
        if (ImGui::GetIO().WantTextInput) {
            schedule.wantAt(now + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(kTextCursorSeconds)));
        }
    }

    if (wasMinimised) {
        stats.minimisedSeconds +=
            std::chrono::duration<double>(Clock::now() - minimisedSince).count();
    }
    if (!flags.stats.empty()) {
        stats.tracer = worker.totals();
        stats.width = shown.bgra.width;
        stats.height = shown.bgra.height;
        stats.samples = shown.preview ? 0 : shown.settings.samplesPerPixel;
        stats.scene = scene->source;
        stats.triangles = scene->scene.triangles.size();
        stats.hover = readouts.hover();
        stats.rectangle = readouts.rectangleMean();
        if (!writeRunStats(flags.stats, stats, error)) {
            std::fprintf(stderr, "raylab: %s\n", error.c_str());
            exitCode = 1;
        }
    }
    if (!command.screenshot.empty()) {
        if (shown.bgra.width > 0 && !shown.preview) {
            if (!saveScreenshot(command.screenshot, shown, error,
                                {panel.bookmarks, observer.keptLabCamera()})) {
                std::fprintf(stderr, "raylab: %s\n", error.c_str());
                exitCode = 1;
            }
        } else {
            std::fprintf(stderr, "raylab: %s not written: no finished picture was shown\n",
                         command.screenshot.c_str());
            exitCode = 1;
        }
    }
    return exitCode;
}

} // namespace raylab::viewer
