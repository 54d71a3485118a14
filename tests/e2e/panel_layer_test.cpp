// PanelLayer without GL (Dear ImGui builds the draw data headless; the cache is never created):
// the panel draws throttled copies of the settings and numbers, so navigation and window timings
// leave its draw data unchanged between refreshes, while the live settings stay live; the panel
// in use draws the live settings; nextWake asks for the frame at which a copy catches up; an
// edit counts only when the panel changed the copy it was offered.

#include "headless_imgui.h"
#include "panel_layer.h"
#include "panel_signature.h"

#include <cfloat>
#include <gtest/gtest.h>
#include <imgui.h>

namespace raylab::viewer {
namespace {

using TimePoint = PanelLayer::TimePoint;
using Ms = std::chrono::milliseconds;

const TimePoint kStart = TimePoint{} + std::chrono::hours(1);

// The layer at a 1280 x 720 display with no mouse over it, periods 250 ms (numbers) and 100 ms
// (settings).
class ViewerPanelLayer : public ::testing::Test {
protected:
    ViewerPanelLayer() : layer(Ms(250), Ms(100)) {
        ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        state.scenePath = "cornell";
        view.sceneName = "cornell";
        view.triangles = 30;
    }

    // One frame of the layer's panel at `now`; the signature of its draw data.
    PanelSignature frame(TimePoint now, bool inUse = false) {
        ImGui::NewFrame();
        layer.draw(state, view, numbers, inUse, now);
        ImGui::Render();
        return panelSignature(*ImGui::GetDrawData());
    }
    // A few frames at `now`, as after an event (ImGui settles: hover, auto-resize).
    PanelSignature settled(TimePoint now) {
        PanelSignature last;
        for (int i = 0; i < 4; ++i) {
            last = frame(now);
        }
        return last;
    }

    HeadlessImGui imgui;
    PanelLayer layer;
    PanelState state; // the live state
    PanelView view;
    PanelNumbers numbers; // the live numbers
};

TEST_F(ViewerPanelLayer, NavigationShowsAtMostOncePerPeriodAndStaysLive) {
    EXPECT_EQ(layer.nextWake(state.settings, numbers), std::optional<TimePoint>(TimePoint{}))
        << "nothing drawn yet: a frame at once";
    const PanelSignature still = settled(kStart);
    EXPECT_FALSE(layer.nextWake(state.settings, numbers).has_value());

    // The camera moves (a held key) 17 ms later: the panel still draws the copy...
    state.settings.camera.position.z += 0.5f;
    const RenderSettings moved = state.settings;
    EXPECT_EQ(frame(kStart + Ms(17)), still);
    // ... and the live settings are the moved ones, not the copy drawn.
    EXPECT_EQ(state.settings, moved);
    EXPECT_EQ(layer.nextWake(state.settings, numbers), std::optional<TimePoint>(kStart + Ms(100)));
    EXPECT_EQ(frame(kStart + Ms(99)), still);

    // At the catch-up the panel draws the live settings and asks for no more frames.
    const PanelSignature caughtUp = frame(kStart + Ms(100));
    EXPECT_NE(caughtUp.hash, still.hash);
    EXPECT_EQ(state.settings, moved);
    EXPECT_FALSE(layer.nextWake(state.settings, numbers).has_value());
}

TEST_F(ViewerPanelLayer, ThePanelInUseDrawsTheLiveSettings) {
    const PanelSignature still = settled(kStart);
    state.settings.light.intensity += 1.0f;
    const RenderSettings edited = state.settings;
    EXPECT_NE(frame(kStart + Ms(17), true).hash, still.hash);
    EXPECT_EQ(state.settings, edited);
    EXPECT_FALSE(layer.nextWake(state.settings, numbers).has_value());
}

TEST_F(ViewerPanelLayer, NumbersShowANewPictureAtTheNextRefreshOnly) {
    const PanelSignature still = settled(kStart);
    // Window timings change every frame: they ask for no frame and change no pixel meanwhile.
    numbers.frameMs.push(16.0f);
    numbers.drawMs.push(3.0f);
    EXPECT_FALSE(layer.nextWake(state.settings, numbers).has_value());
    EXPECT_EQ(frame(kStart + Ms(17)), still);
    // A new picture asks for the frame of the next refresh, and shows then.
    numbers.picture = {1280, 720, 64, false, true, 40.0, 2.5e7};
    EXPECT_EQ(layer.nextWake(state.settings, numbers), std::optional<TimePoint>(kStart + Ms(250)));
    EXPECT_EQ(frame(kStart + Ms(249)), still);
    EXPECT_NE(frame(kStart + Ms(250)).hash, still.hash);
    EXPECT_FALSE(layer.nextWake(state.settings, numbers).has_value());
}

TEST_F(ViewerPanelLayer, NextWakeIsTheEarlierCatchUp) {
    settled(kStart);
    numbers.picture.samples = 4; // the numbers' copy catches up at 250 ms
    state.settings.camera.position.x += 1.0f;
    frame(kStart + Ms(200)); // the settings' copy follows; its next change waits to 300 ms
    state.settings.camera.position.x += 1.0f;
    EXPECT_EQ(layer.nextWake(state.settings, numbers), std::optional<TimePoint>(kStart + Ms(250)));
    frame(kStart + Ms(250));
    EXPECT_EQ(layer.nextWake(state.settings, numbers), std::optional<TimePoint>(kStart + Ms(300)));
    frame(kStart + Ms(300));
    EXPECT_FALSE(layer.nextWake(state.settings, numbers).has_value());
    numbers.picture.samples = 8; // at 500 ms
    state.settings.camera.position.x += 1.0f;
    EXPECT_EQ(layer.nextWake(state.settings, numbers), std::optional<TimePoint>(kStart + Ms(400)));
}

TEST(ViewerPanelEdit, OnlyAChangeOfTheCopyOfferedCounts) {
    RenderSettings live, offered, drawn;
    live.camera.position.z = -2.0f; // navigated since the copy offered was made
    offered.camera.position.z = -3.0f;
    drawn = offered;
    EXPECT_EQ(settingsAfterPanel(live, offered, drawn), live); // untouched: the live ones stay
    drawn.light.intensity += 1.0f;
    EXPECT_EQ(settingsAfterPanel(live, offered, drawn), drawn); // an edit of the copy wins
}

} // namespace
} // namespace raylab::viewer
