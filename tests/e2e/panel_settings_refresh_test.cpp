// The panel's copy of the settings while navigating (panel_settings_refresh.h): it follows the
// live settings at most once a period, at once when the panel is in use, and catches up.

#include "panel_settings_refresh.h"

#include <gtest/gtest.h>

namespace raylab::viewer {
namespace {

using TimePoint = PanelSettingsRefresh::TimePoint;
using Ms = std::chrono::milliseconds;

const TimePoint kStart = TimePoint{} + std::chrono::hours(1);

RenderSettings movedTo(float z) {
    RenderSettings s;
    s.camera.position.z = z;
    return s;
}

TEST(ViewerPanelSettings, FollowsNavigationAtMostOncePerPeriod) {
    PanelSettingsRefresh refresh(0.1);
    EXPECT_EQ(refresh.shown(movedTo(-3.0f), false, kStart).camera.position.z, -3.0f);
    // The first change after a still period shows at once (a single key press).
    EXPECT_EQ(refresh.shown(movedTo(-2.9f), false, kStart + Ms(500)).camera.position.z, -2.9f);
    // Changes every frame (60 Hz) for 0.28 s: the copy changes only every 100 ms.
    int changes = 0;
    float last = -2.9f;
    for (int frame = 1; frame <= 17; ++frame) {
        const float z = -2.9f + 0.01f * static_cast<float>(frame);
        const RenderSettings& shown =
            refresh.shown(movedTo(z), false, kStart + Ms(500) + Ms(frame * 1000 / 60));
        if (shown.camera.position.z != last) {
            ++changes;
            last = shown.camera.position.z;
            EXPECT_EQ(shown.camera.position.z, z) << "a refresh copies the live settings";
        }
    }
    EXPECT_EQ(changes, 2); // at 500 + 100 ms and at 500 + 200 ms (frames 6 and 12)
    // Stale now: it catches up one period after its last change.
    const RenderSettings live = movedTo(-2.72f);
    ASSERT_TRUE(refresh.catchUpAt(live).has_value());
    EXPECT_EQ(*refresh.catchUpAt(live), kStart + Ms(500) + Ms(12 * 1000 / 60) + Ms(100));
    EXPECT_EQ(refresh.shown(live, false, *refresh.catchUpAt(live)).camera.position.z, -2.72f);
    EXPECT_FALSE(refresh.catchUpAt(live).has_value());
}

TEST(ViewerPanelSettings, ThePanelInUseAlwaysShowsTheLiveSettings) {
    PanelSettingsRefresh refresh(0.1);
    refresh.shown(movedTo(-3.0f), false, kStart);
    EXPECT_EQ(refresh.shown(movedTo(-2.9f), false, kStart + Ms(17)).camera.position.z, -3.0f);
    EXPECT_EQ(refresh.shown(movedTo(-2.7f), true, kStart + Ms(34)).camera.position.z, -2.7f);
    EXPECT_EQ(refresh.shown(movedTo(-2.6f), true, kStart + Ms(51)).camera.position.z, -2.6f);
}

TEST(ViewerPanelSettings, EveryFieldCounts) {
    PanelSettingsRefresh refresh(0.1);
    RenderSettings live;
    refresh.shown(live, false, kStart);
    live.shadowEpsilon = 0.002f;
    ASSERT_TRUE(refresh.catchUpAt(live).has_value());
    live = RenderSettings{};
    live.light.color.y = 0.5f;
    EXPECT_TRUE(refresh.catchUpAt(live).has_value());
    EXPECT_FALSE(refresh.catchUpAt(RenderSettings{}).has_value());
}

} // namespace
} // namespace raylab::viewer
