// The frame's input: drops, keys, the mouse, the panel, and a replay's events, turned into the
// settings of the job the frame hands the tracer.

#include "core/scene_framing.h"
#include "io/inspection_json.h"
#include "io/screenshot_settings.h"
#include "screenshot.h"
#include "session_state.h"
#include "settings_edit.h"
#include "split_view.h"
#include "viewer_loop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

namespace {

// Render resolution for a side of the picture's box: side * scale, at least 1 and at most the
// maximum.
int renderSide(int pictureSide, float scale) {
    const long side = std::lround(static_cast<double>(pictureSide) * scale);
    return static_cast<int>(std::clamp(side, 1L, static_cast<long>(kMaxImageSide)));
}

bool keyDown(GLFWwindow* window, int key, int otherKey) {
    return glfwGetKey(window, key) == GLFW_PRESS || glfwGetKey(window, otherKey) == GLFW_PRESS;
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

} // namespace

void ViewerLoop::beginFrame() {
    // Another monitor's content scale: the panel's font and sizes follow (not --ui-scale's).
    if (input_.pending().contentScale) {
        uiScale_ = monitorUiScale();
        gui_->setScale(uiScale_);
    }
    layout_ = layoutOf(fbWidth_, fbHeight_);
    gui_->beginFrame();
    if (!pictureToUpload_) {
        return;
    }
    quad_.upload(shown_.bgra);
    stats_.uploads.add(quad_.lastUploadSeconds());
    RenderJob view{shown_.scene, shown_.settings};
    view.settings.width = shown_.bgra.width; // a preview's view at its shown size
    view.settings.height = shown_.bgra.height;
    if (!samePicture(view, lastView_)) {
        ++stats_.viewsShown;
        lastView_ = view;
    }
    if (shown_.passSeconds > 0.0) {
        numbers_.passMs.push(static_cast<float>(shown_.passSeconds * 1000.0));
    }
    numbers_.uploadMs = quad_.lastUploadSeconds() * 1000.0;
    numbers_.picture = pictureFacts(shown_);
    if (numbers_.picture.noisePercent >= 0.0) {
        numbers_.noisePercent.push(static_cast<float>(numbers_.picture.noisePercent));
    }
    pictureToUpload_ = false;
}

void ViewerLoop::handleInput() {
    meanIndirectWanted_ = false;
    inspectWanted_ = false;
    observerWanted_ = false; // O or the panel's checkbox
    events_ = input_.take();
    if (replay_) {
        applyReplay(events_);
    } else {
        if (!pendingDrop_.empty() && framesShown_ > 0) {
            events_.dropped.push_back(pendingDrop_); // --drop: as if dropped once the window shows
            pendingDrop_.clear();
        }
        applyDrops(events_.dropped);
        // Escape cancels a running load (even while the panel has the keyboard) instead of
        // quitting.
        if (const auto escape =
                std::find(events_.keys.begin(), events_.keys.end(), GLFW_KEY_ESCAPE);
            escape != events_.keys.end() && loader_.busy()) {
            events_.keys.erase(escape);
            cancelLoad();
        }
        applyKeysAndMouse(events_);
    }
    readouts_.update(window_.handle(), events_, ImGui::GetIO().WantCaptureMouse, layout_.picture,
                     shown_);
    inspect();
    if (layout_.panelShown()) { // F1 hides it; a window too narrow for it has none
        drawPanelColumn();
    }
    if (observerWanted_) {
        observer_.toggle(panel_.settings, scene_->scene.bounds());
    }
    if (meanIndirectWanted_) {
        if (useMeanIndirect(numbers_.picture, panel_.settings)) {
            const glm::vec3 n = panel_.settings.indirect3();
            char text[96];
            std::snprintf(
                text, sizeof text, "the lab's N set to the mean path-traced N, %.3f %.3f %.3f",
                static_cast<double>(n.x), static_cast<double>(n.y), static_cast<double>(n.z));
            setStatus(text, false);
        } else {
            setStatus("no path-traced picture yet: its mean N is not known", true);
        }
    }
    // The job: the panel's settings at the picture box's resolution times the scale (a replay's
    // at the recorded resolution).
    if (!replay_) {
        panel_.settings.width = renderSide(layout_.picture.width, panel_.resolutionScale);
        panel_.settings.height = renderSide(layout_.picture.height, panel_.resolutionScale);
        observer_.history().observe(panel_.settings, wokeAt_);
    }
    submitJob();
}

// A dropped mesh opens; a dropped screenshot (.png or .json) restores its scene, settings, size
// and bookmarks.
void ViewerLoop::applyDrops(const std::vector<std::string>& dropped) {
    for (const std::string& path : dropped) {
        if (!isScreenshotPath(path)) {
            panel_.scenePath = path;
            loader_.start(path); // replaces a running load
            pendingRestore_.reset();
            continue;
        }
        RenderSettings restored;
        SettingsJsonExtras extras;
        std::string why;
        if (!readScreenshotSettings(path, restored, extras, why)) {
            setStatus(why, true);
            continue;
        }
        panel_.bookmarks = extras.bookmarks;
        panel_.resolutionScale = 1.0f;
        sizeWindowFor(restored.width, restored.height);
        const std::string restoredScene = extras.scene.empty() ? scene_->source : extras.scene;
        if (restoredScene == scene_->source) {
            observer_.leave(panel_.settings);
            panel_.settings = restored;
            if (extras.observedLabCamera) { // the observer's picture, the lab camera kept
                observer_.observe(*extras.observedLabCamera, restored.camera, panel_.settings);
            }
        } else {
            loader_.start(restoredScene);
            pendingRestore_ = restored; // applied when the scene has loaded
            pendingLab_ = extras.observedLabCamera;
            panel_.scenePath = restoredScene;
        }
        setStatus("restored " + path, false);
    }
}

// The navigation keys' presses and releases of this frame, handed to the held keys, then their
// motion up to now applied to the settings (the motion as a whole is refused when it would make
// them invalid). Presses while ImGui wants the keyboard are its own; then no key stays held.
void ViewerLoop::applyHeldKeys(const std::vector<NavKeyChange>& changes) {
    const bool panelHasKeyboard = ImGui::GetIO().WantCaptureKeyboard;
    for (const NavKeyChange& change : changes) {
        switch (change.kind) {
        case NavKeyChange::Kind::Press:
            if (!panelHasKeyboard) {
                held_.press(change.action, change.when);
            }
            break;
        case NavKeyChange::Kind::Release: held_.release(change.action, change.when); break;
        case NavKeyChange::Kind::FocusLost: held_.releaseAll(change.when); break;
        }
    }
    if (panelHasKeyboard) {
        held_.releaseAll(wokeAt_);
    }
    RenderSettings next = panel_.settings;
    for (const NavMotion& motion : held_.advance(wokeAt_)) {
        applyNavAction(motion.action, step_, next, motion.steps);
    }
    std::string ignored;
    acceptEdit(next, panel_.settings, ignored);
}

// The mouse drag's turn since its last update applied to `settings`; `start`: a press outside the
// panel happened now.
void ViewerLoop::applyDrag(bool start, RenderSettings& settings) {
    float yaw = 0.0f, pitch = 0.0f;
    drag_.update(window_.handle(), start,
                 settings.camera.verticalFovDegrees /
                     static_cast<float>(std::max(layout_.picture.height, 1)),
                 yaw, pitch);
    if (yaw != 0.0f || pitch != 0.0f) {
        turnCamera(yaw, pitch, settings);
    }
}

// Keys, wheel and drags of this frame applied to the settings (those ImGui wants go to ImGui).
// Navigation keys move by a step per press and smoothly while held (held_keys.h).
void ViewerLoop::applyKeysAndMouse(const InputEvents& events) {
    const ImGuiIO& io = ImGui::GetIO();
    GLFWwindow* window = window_.handle();
    applyHeldKeys(events.navKeys);
    RenderSettings next = panel_.settings;
    for (const int key : events.keys) {
        if (const auto slot = bookmarkForKey(key); slot && !io.WantCaptureKeyboard) {
            std::optional<Camera>& bookmark =
                panel_.bookmarks.slots[static_cast<std::size_t>(*slot)];
            if (keyDown(window, GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL)) {
                bookmark = next.camera;
            } else if (bookmark) {
                next.camera = *bookmark;
            }
        }
        const auto command = commandForKey(key);
        if (!command) {
            continue;
        }
        switch (*command) {
        case Command::Screenshot: ++screenshots_; continue;
        case Command::TogglePanel: showPanel_ = !showPanel_; continue;
        default: break;
        }
        if (io.WantCaptureKeyboard) {
            continue; // typed into the panel
        }
        switch (*command) {
        case Command::UseMeanIndirect: meanIndirectWanted_ = true; break;
        case Command::ToggleSplit: panel_.split = !panel_.split; break;
        case Command::NextCompareMode:
            // The difference needs two sides: it turns the split on.
            panel_.compareMode = panel_.compareMode == CompareMode::Wipe ? CompareMode::Difference
                                                                         : CompareMode::Wipe;
            panel_.split = panel_.split || panel_.compareMode == CompareMode::Difference;
            break;
        case Command::Undo:
        case Command::Redo:
            if (keyDown(window, GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL)) {
                const bool redo = *command == Command::Redo ||
                                  keyDown(window, GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
                SettingsHistory& history = observer_.history();
                if (redo ? history.redo(next) : history.undo(next)) {
                    panel_.settings = next;
                }
            }
            break;
        case Command::ToggleObserver: observerWanted_ = true; break;
        case Command::ToggleKeyList: showKeys_ = !showKeys_; break;
        case Command::KeepSnapshot:
            panel_.snapshot = next;
            panel_.compareSnapshot = true;
            panel_.split = true;
            break;
        case Command::NextView:
            next.view = nextView(
                next.view, keyDown(window, GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT) ? -1 : 1);
            break;
        case Command::Quit: quit_ = true; break;
        case Command::Screenshot:
        case Command::TogglePanel: break; // above
        }
    }
    if (!io.WantCaptureMouse && events.scroll != 0.0) {
        moveCamera(static_cast<float>(events.scroll) * step_, next);
    }
    if (events.inspectPressed && !io.WantCaptureMouse) {
        double x = 0.0, y = 0.0;
        cursorInPixels(window, x, y);
        int px = 0, py = 0;
        if (pixelUnderCursor(x, y, layout_.picture, panel_.settings.width, panel_.settings.height,
                             px, py)) {
            panel_.inspected = InspectedPixel{px, py, panel_.settings.camera, panel_.settings.width,
                                              panel_.settings.height};
            inspectWanted_ = true;
        }
    }
    applyOrbitAndPan(events, io.WantCaptureMouse, window, *scene_, layout_.picture, orbit_, next);
    const bool press = events.leftPressed && !io.WantCaptureMouse;
    const bool onDivider = panel_.split && panel_.compareMode == CompareMode::Wipe &&
                           dividerDrag_.update(window, press, layout_.picture, panel_.divider);
    applyDrag(press && !onDivider, next);
    std::string ignored;
    acceptEdit(next, panel_.settings, ignored);
}

// The inspected pixel's numbers, for the panel (a few rays, on this thread); printed as JSON
// (raylab-render --inspect's) on standard output when a click asks, for scripts.
void ViewerLoop::inspect() {
    inspection_.reset();
    if (!panel_.inspected) {
        return;
    }
    inspection_ = inspectPixel(scene_->scene, scene_->bvh, scene_->emitters,
                               inspectionSettings(panel_.settings, *panel_.inspected),
                               panel_.inspected->x, panel_.inspected->y);
    if (inspectWanted_) {
        std::printf("%s\n", inspectionToJson(*inspection_).c_str());
        std::fflush(stdout);
    }
}

void ViewerLoop::drawPanelColumn() {
    PanelView view;
    const float perUnit = window_.framebufferScale(); // framebuffer pixels per unit
    view.width = static_cast<float>(layout_.panel.width) / perUnit;
    view.minWidth = kMinPanelColumnWidth * uiScale_;
    view.maxWidth = static_cast<float>(fbWidth_ - 1) / perUnit; // a pixel of picture
    view.sceneName = scene_->source;
    view.triangles = scene_->scene.triangles.size();
    view.loading = loader_.progress();
    view.step = step_;
    view.maxEpsilon = maxEpsilon_;
    view.hasEmitters = !scene_->emitters.empty();
    view.observer = observer_.on();
    view.inspection = inspection_ ? &*inspection_ : nullptr;
    view.hover = readouts_.hover() ? &*readouts_.hover() : nullptr;
    view.rectangle = readouts_.rectangleMean() ? &*readouts_.rectangleMean() : nullptr;
    const ImGuiIO& io = ImGui::GetIO();
    const RenderSettings live = panel_.settings;
    const PanelActions actions = panelLayer_.draw(
        panel_, std::move(view), numbers_, io.WantCaptureMouse || io.WantCaptureKeyboard, wokeAt_);
    if (actions.resizedTo > 0.0f) { // its edge dragged: the picture gets the rest
        panelUnits_ = actions.resizedTo / uiScale_;
        layout_ = layoutOf(fbWidth_, fbHeight_);
    }
    if (replay_) {
        panel_.settings = live; // the replay decides every setting: the panel only shows them
        return;
    }
    screenshots_ += actions.screenshot ? 1 : 0;
    if (actions.frameScene) {
        frameScene(scene_->scene, panel_.settings);
    }
    if (actions.resetToLab) {
        observer_.leave(panel_.settings); // the lab's defaults are the lab camera's
        resetToLabDefaults(scene_->scene, isLabBoxName(scene_->source), panel_.settings);
    }
    if (actions.openScene) {
        loader_.start(panel_.scenePath); // replaces a running load
        pendingRestore_.reset();
    }
    if (actions.cancelLoad) {
        cancelLoad();
    }
    meanIndirectWanted_ = meanIndirectWanted_ || actions.useMeanIndirect;
    observerWanted_ = observerWanted_ || actions.toggleObserver;
    if (actions.keepSnapshot) {
        panel_.snapshot = panel_.settings;
        panel_.compareSnapshot = true;
        panel_.split = true;
    }
}

// A replay: the window's own keys only show and hide (F1, H) or quit (Escape); the recording's
// events of this frame decide everything else. It waits (counting no frames) while its scene
// loads and until a screenshot's picture is saved.
void ViewerLoop::applyReplay(const InputEvents& events) {
    for (const int key : events.keys) {
        const auto command = commandForKey(key);
        if (command == Command::Quit) {
            quit_ = true;
        } else if (command == Command::TogglePanel) {
            showPanel_ = !showPanel_;
        } else if (command == Command::ToggleKeyList) {
            showKeys_ = !showKeys_;
        }
    }
    if (!replay_->pendingScreenshot() && !loader_.busy() &&
        replay_->state().scene == scene_->source) {
        replay_->advance();
    }
    const RecordedState& state = replay_->state();
    if (state.scene != scene_->source) {
        if (!loader_.busy()) {
            panel_.scenePath = state.scene;
            loader_.start(state.scene);
        }
        return;
    }
    if (state.labCamera) {
        if (observer_.keptLabCamera() != state.labCamera) {
            observer_.observe(*state.labCamera, state.settings.camera, panel_.settings);
        }
    } else if (observer_.on()) {
        observer_.leave(panel_.settings);
    }
    panel_.settings = state.settings;
    panel_.bookmarks = state.bookmarks;
    const std::optional<InspectedPixel> inspected = inspectedPixel(state);
    inspectWanted_ = inspected && inspected != panel_.inspected; // printed as the click was
    panel_.inspected = inspected;
    panel_.split = state.compare.has_value();
    char text[160];
    std::snprintf(text, sizeof text, "replaying %s: frame %ld of %ld%s", flags_.replay.c_str(),
                  replay_->frame(), replay_->frames(),
                  replay_->pendingScreenshot() ? ", rendering a screenshot" : "");
    panel_.status = text;
    panel_.statusIsError = false;
    quit_ = quit_ || replay_->finished();
}

} // namespace raylab::viewer
