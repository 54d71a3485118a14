#include "viewer_app.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glad/gl.h>
#include <imgui.h>
#include <string>

#define GLFW_INCLUDE_NONE
#include "core/scene_framing.h"
#include "gl_window.h"
#include "history.h"
#include "image_quad.h"
#include "input.h"
#include "key_relay.h"
#include "panel.h"
#include "panel_context.h"
#include "render_worker.h"
#include "run_stats.h"
#include "scene_loader.h"
#include "screenshot.h"
#include "settings_edit.h"

#include <GLFW/glfw3.h>

namespace raylab::viewer {

namespace {

using Clock = std::chrono::steady_clock;

bool isLabBox(const LoadedScene& scene) { return scene.source == "cornell"; }

// Render resolution for a framebuffer side: side * scale, at least 1 and at most the maximum.
int renderSide(int framebufferSide, float scale) {
    const long side = std::lround(static_cast<double>(framebufferSide) * scale);
    return static_cast<int>(std::clamp(side, 1L, static_cast<long>(kMaxImageSide)));
}

// Keys, wheel and drag of this frame applied to the settings (those ImGui wants go to ImGui).
void applyInput(const InputEvents& events, GLFWwindow* window, float step, int framebufferHeight,
                MouseDrag& drag, PanelState& panel, bool& showPanel, int& screenshots, bool& quit) {
    const ImGuiIO& io = ImGui::GetIO();
    RenderSettings next = panel.settings;
    for (const int key : events.keys) {
        if (const auto command = commandForKey(key)) {
            if (*command == Command::Screenshot) {
                ++screenshots;
            } else if (*command == Command::TogglePanel) {
                showPanel = !showPanel;
            } else if (!io.WantCaptureKeyboard) {
                quit = true;
            }
        } else if (const auto action = navActionForKey(key); action && !io.WantCaptureKeyboard) {
            applyNavAction(*action, step, next);
        }
    }
    if (!io.WantCaptureMouse && events.scroll != 0.0) {
        moveCamera(static_cast<float>(events.scroll) * step, next);
    }
    float yaw = 0.0f, pitch = 0.0f;
    drag.update(window, events.leftPressed && !io.WantCaptureMouse,
                next.camera.verticalFovDegrees / static_cast<float>(std::max(framebufferHeight, 1)),
                yaw, pitch);
    if (yaw != 0.0f || pitch != 0.0f) {
        turnCamera(yaw, pitch, next);
    }
    std::string ignored;
    acceptEdit(next, panel.settings, ignored);
}

void setStatus(PanelState& panel, const std::string& text, bool isError) {
    panel.status = text;
    panel.statusIsError = isError;
    std::fprintf(stderr, "raylab: %s\n", text.c_str());
}

} // namespace

int runViewer(const ViewerOptions& options, std::shared_ptr<const LoadedScene> scene) {
    const CommandLine& command = options.command;
    GlWindow window;
    std::string error;
    if (!window.open(command.settings.width, command.settings.height, "raylab - " + scene->source,
                     error)) {
        std::fprintf(stderr, "raylab: %s\n", error.c_str());
        return 1;
    }
    InputCollector input;
    input.attach(window.handle()); // before ImGui, whose callbacks chain to these
    PanelContext gui(window.handle());
    ImageQuad quad;
    if (!gui.ok() || !quad.create(error)) {
        std::fprintf(stderr, "raylab: %s\n", gui.ok() ? error.c_str() : "cannot start Dear ImGui");
        return 1;
    }
    KeyRelay keys(window.handle()); // in front of ImGui's key callbacks
    SceneLoader loader;
    RenderWorker worker; // declared last: stopped and joined first

    PanelState panel;
    panel.settings = command.settings;
    panel.scenePath = scene->source;
    panel.resolutionScale = options.resolutionScale;
    bool showPanel = options.showPanel;
    float step = navigationStep(scene->scene.bounds());
    float maxEpsilon = 100.0f * scaledShadowEpsilon(scene->scene.bounds());

    MouseDrag drag;
    ShownImage shown;
    RenderJob submitted;
    uint64_t submittedSerial = 0;
    History frameMs(120), passMs(120);
    int framesShown = 0;
    int screenshots = 0;
    bool quit = false;
    int exitCode = 0;
    const bool scripted = command.frames > 0;
    // PFM and EXR screenshots are written from the linear picture.
    const bool keepLinear = !command.screenshot.empty() &&
                            std::filesystem::path(command.screenshot).extension() != ".png";
    const bool needsFinal = !command.screenshot.empty() || !options.readback.empty();
    const auto framePeriod = std::chrono::duration<double>(1.0 / kFramesPerSecond);
    auto previousFrameTime = Clock::now();
    auto nextFrame = previousFrameTime;
    RunStats stats;
    bool wasMinimised = false;
    auto minimisedSince = previousFrameTime;

    for (;;) {
        // Pace the loop; events (collected by the callbacks) wake it early, but frames stay paced.
        for (auto now = Clock::now(); now < nextFrame; now = Clock::now()) {
            glfwWaitEventsTimeout(std::chrono::duration<double>(nextFrame - now).count());
        }
        glfwPollEvents();
        nextFrame = std::max(nextFrame + std::chrono::duration_cast<Clock::duration>(framePeriod),
                             Clock::now());
        quit = quit || glfwWindowShouldClose(window.handle()) != 0;

        if (auto loaded = loader.poll()) {
            if (loaded->scene) {
                scene = loaded->scene;
                step = navigationStep(scene->scene.bounds());
                maxEpsilon = 100.0f * scaledShadowEpsilon(scene->scene.bounds());
                placeForScene(scene->scene, isLabBox(*scene), panel.settings);
                glfwSetWindowTitle(window.handle(), ("raylab - " + scene->source).c_str());
                setStatus(panel,
                          "loaded " + scene->source +
                              (loaded->warnings.empty() ? "" : " (" + loaded->warnings + ")"),
                          false);
            } else {
                setStatus(panel, loaded->error, true);
            }
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
            }
            wasMinimised = minimised;
        }
        if (minimised) {
            if (quit) {
                break;
            }
            continue; // nothing to draw; the tracer keeps its job and stops at the sample cap
        }

        gui.beginFrame();
        if (worker.takeLatest(shown)) {
            quad.upload(shown.image);
            stats.uploads.add(quad.lastUploadSeconds());
            if (shown.passSeconds > 0.0) {
                passMs.push(static_cast<float>(shown.passSeconds * 1000.0));
            }
        }
        applyInput(input.take(), window.handle(), step, fbHeight, drag, panel, showPanel,
                   screenshots, quit);
        if (showPanel) {
            PanelView view;
            view.shown = &shown;
            view.sceneName = scene->source;
            view.triangles = scene->scene.triangles.size();
            view.loading = loader.busy();
            view.step = step;
            view.maxEpsilon = maxEpsilon;
            view.frameMs = &frameMs;
            view.passMs = &passMs;
            view.uploadMs = quad.lastUploadSeconds() * 1000.0;
            const PanelActions actions = drawPanel(panel, view);
            screenshots += actions.screenshot ? 1 : 0;
            if (actions.frameScene) {
                frameScene(scene->scene, panel.settings);
            }
            if (actions.resetToLab) {
                resetToLabDefaults(scene->scene, isLabBox(*scene), panel.settings);
            }
            if (actions.openScene && !loader.start(panel.scenePath)) {
                setStatus(panel, "a scene is loading already", true);
            }
        }

        // The job: the panel's settings at the framebuffer's resolution times the scale.
        panel.settings.width = renderSide(fbWidth, panel.resolutionScale);
        panel.settings.height = renderSide(fbHeight, panel.resolutionScale);
        const RenderJob job{scene, panel.settings, keepLinear};
        if (submittedSerial == 0 || !sameJob(job, submitted)) {
            submittedSerial = worker.submit(job);
            submitted = job;
        }
        // A picture of the current job that settings reproduce exactly.
        const bool current =
            shown.jobSerial == submittedSerial && !shown.preview && shown.image.width > 0;
        const bool scriptEnds = scripted && framesShown + 1 >= command.frames &&
                                (!needsFinal || (current && shown.final));
        const bool finalFrame = quit || scriptEnds;

        glViewport(0, 0, fbWidth, fbHeight);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        quad.draw(fbWidth, fbHeight);
        if (screenshots > 0 && current) {
            std::string path;
            if (saveNumberedScreenshot(command.screenshotDir, shown, path, error)) {
                setStatus(panel, "saved " + path, false);
            } else {
                setStatus(panel, "screenshot not saved: " + error, true);
            }
            screenshots = 0;
        }
        gui.endFrame();
        keys.frameEnded();
        if (finalFrame && !options.readback.empty()) {
            if (!writePng(options.readback, readFramebuffer(fbWidth, fbHeight), error)) {
                std::fprintf(stderr, "raylab: %s\n", error.c_str());
                exitCode = 1;
            }
        }
        glfwSwapBuffers(window.handle());
        ++framesShown;
        const auto now = Clock::now();
        const double interval = std::chrono::duration<double>(now - previousFrameTime).count();
        frameMs.push(static_cast<float>(interval * 1000.0));
        previousFrameTime = now;
        if (stats.framesShown++ > 0) { // the first swap starts the clock
            stats.frameIntervals.add(interval);
            stats.shownSeconds += interval;
            stats.slowFrames += interval > 1.0 / 30.0 ? 1 : 0;
        }
        if (finalFrame) {
            break;
        }
    }

    if (wasMinimised) {
        stats.minimisedSeconds +=
            std::chrono::duration<double>(Clock::now() - minimisedSince).count();
    }
    if (!options.stats.empty()) {
        stats.tracer = worker.totals();
        stats.width = shown.image.width;
        stats.height = shown.image.height;
        stats.samples = shown.preview ? 0 : shown.settings.samplesPerPixel;
        stats.scene = scene->source;
        stats.triangles = scene->scene.triangles.size();
        if (!writeRunStats(options.stats, stats, error)) {
            std::fprintf(stderr, "raylab: %s\n", error.c_str());
            exitCode = 1;
        }
    }
    if (!command.screenshot.empty()) {
        if (shown.image.width > 0 && !shown.preview) {
            if (!saveScreenshot(command.screenshot, shown, error)) {
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
