// The frame drawn: the picture in its box, the overlays over it, the panel, the screenshots the
// frame saves, the swap, and the frame's timing.

#include "key_list.h"
#include "observer_geometry.h"
#include "ray_overlay_geometry.h"
#include "screenshot.h"
#include "session_state.h"
#include "split_view.h"
#include "viewer_loop.h"

#include <cstdio>
#include <glad/gl.h>
#include <imgui.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

namespace {

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

} // namespace

void ViewerLoop::drawFrame() {
    // A picture of the current job that settings reproduce exactly.
    const bool current =
        shown_.jobSerial == submittedSerial_ && !shown_.preview && shown_.bgra.width > 0;
    const bool scriptEnds = scripted_ && framesShown_ + 1 >= command_.frames &&
                            (!needsFinal_ || (current && shown_.final));
    finalFrame_ = quit_ || scriptEnds;

    // The picture, when there is one, covers every pixel of its box.
    clearUncovered(layout_, quad_.hasImage());
    quad_.draw(layout_);
    drawOverlays();
    saveScreenshots(current);
    if (showKeys_) { // centred on the picture
        const float perUnit = window_.framebufferScale();
        drawKeyList((static_cast<float>(layout_.picture.x) +
                     0.5f * static_cast<float>(layout_.picture.width)) /
                        perUnit,
                    (static_cast<float>(layout_.picture.y) +
                     0.5f * static_cast<float>(layout_.picture.height)) /
                        perUnit);
    }
    panelLayer_.composite(gui_->endFrame(), fbWidth_, fbHeight_);
    keys_->frameEnded();
    if (finalFrame_ && !flags_.readback.empty()) {
        std::string error;
        if (!writePng(flags_.readback, readFramebuffer(fbWidth_, fbHeight_), error)) {
            std::fprintf(stderr, "raylab: %s\n", error.c_str());
            exitCode_ = 1;
        }
    }
    glfwSwapBuffers(window_.handle());
    countFrame(wokeAt_);
}

void ViewerLoop::drawOverlays() {
    if (shown_.compare && shown_.compareMode == CompareMode::Wipe) {
        drawDivider(layout_, splitColumn(layout_.picture.width, shown_.divider));
    }
    if (const auto lab = observer_.keptLabCamera(); lab && shown_.bgra.width > 0) {
        // The lab camera and the light, seen with the camera of the picture shown (the
        // observer's), over it.
        overlayLines_.draw(observerOverlay(shown_.settings.camera, shown_.bgra.width,
                                           shown_.bgra.height, *lab, panel_.settings.width,
                                           panel_.settings.height, panel_.settings.light,
                                           scene_->scene.bounds(), kNearDepthPerStep * step_),
                           shown_.bgra.width, shown_.bgra.height, layout_);
    }
    if (inspection_ && shown_.bgra.width > 0 && shown_.bgra.height > 0) {
        // Its rays, pinned in the world, seen with the camera of the picture shown (so they move
        // with the picture); the marker while that picture is the one it was picked in.
        RenderSettings picture = shown_.settings;
        picture.width = shown_.bgra.width;
        picture.height = shown_.bgra.height;
        const std::vector<ImageSegment> rays =
            projectSegments(PrimaryRays(picture.camera, picture.width, picture.height),
                            picture.width, picture.height, kNearDepthPerStep * step_,
                            inspectionSegments(*inspection_, panel_.inspected->camera.position));
        overlayLines_.draw(rays, picture.width, picture.height, layout_);
        if (seenAsPicked(picture, *panel_.inspected)) {
            drawPixelMarker(layout_, panel_.inspected->x, panel_.inspected->y, picture.width,
                            picture.height);
        }
    }
    if (const auto& r = readouts_.rectangle()) {
        drawPixelRectangle(layout_, r->x0, r->y0, r->x1, r->y1, shown_.bgra.width,
                           shown_.bgra.height);
    }
}

// Screenshots asked for (F12, the panel's button) are saved with the first current picture; a
// replay saves each recorded screenshot once its picture has the recorded samples.
void ViewerLoop::saveScreenshots(bool current) {
    const bool replayShot = replay_ && replay_->pendingScreenshot() && current &&
                            !shown_.linear.pixels.empty() &&
                            isScreenshotPicture(shown_.settings, shown_.compare, shown_.preview,
                                                *replay_->pendingScreenshot());
    if (!replayShot && (screenshots_ == 0 || !current || shown_.linear.pixels.empty())) {
        return;
    }
    std::string path, error;
    if (saveNumberedScreenshot(command_.screenshotDir, shown_, path, error,
                               {panel_.bookmarks, observer_.keptLabCamera()})) {
        setStatus("saved " + path, false);
        if (recorder_) {
            recorder_->screenshot(framesShown_,
                                  {shown_.settings.samplesPerPixel,
                                   shown_.compare ? shown_.compare->samplesPerPixel : 0});
        }
    } else {
        setStatus("screenshot not saved: " + error, true);
        if (replayShot) {
            exitCode_ = 1; // the replay's screenshot is its result
        }
    }
    if (replayShot) {
        replay_->screenshotTaken();
    }
    screenshots_ = 0;
}

// The frame's timing, for the panel's plots and --stats.
void ViewerLoop::countFrame(TimePoint wokeAt) {
    ++framesShown_;
    drawnWidth_ = fbWidth_;
    drawnHeight_ = fbHeight_;
    const auto now = Clock::now();
    const double interval = secondsBetween(previousFrameTime_, now);
    const double response = schedule_.frameShown(now);
    numbers_.frameMs.push(static_cast<float>(interval * 1000.0));
    numbers_.drawMs.push(static_cast<float>(secondsBetween(wokeAt, now) * 1000.0));
    stats_.drawTimes.add(secondsBetween(wokeAt, now));
    previousFrameTime_ = now;
    if (stats_.framesShown++ > 0) { // the first swap starts the clock
        stats_.frameResponses.add(response);
        stats_.shownSeconds += interval;
        stats_.slowFrames += response > 1.0 / 30.0 ? 1 : 0;
    }
}

} // namespace raylab::viewer
