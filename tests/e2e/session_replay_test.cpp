// --record and --replay without a window: the recorder notes changes only, the replay applies
// events frame by frame and stops at each screenshot, and a window's state survives the trip
// through a recording into the job the replay hands the tracer.

#include "session_recorder.h"
#include "session_replay.h"
#include "session_state.h"

#include <filesystem>
#include <gtest/gtest.h>
#include <unistd.h>

namespace raylab::viewer {
namespace {

namespace fs = std::filesystem;

RecordedState stateAt(float x) {
    RecordedState state;
    state.scene = "cornell";
    state.settings.width = 64;
    state.settings.height = 48;
    state.settings.camera.position.x = x;
    return state;
}

TEST(SessionRecorder, NotesChangesOnlyAndScreenshotsAfterAState) {
    SessionRecorder recorder;
    recorder.screenshot(0, {1, 0}); // no picture asked for yet: nothing to record
    recorder.note(0, stateAt(0.0f));
    recorder.note(1, stateAt(0.0f));
    recorder.note(2, stateAt(0.0f));
    recorder.note(5, stateAt(0.5f));
    recorder.screenshot(6, {3, 0});
    recorder.note(6, stateAt(0.5f));
    recorder.note(9, stateAt(0.0f));
    const SessionRecording& r = recorder.recording();
    ASSERT_EQ(r.events.size(), 4u);
    EXPECT_EQ(r.events[0].frame, 0);
    EXPECT_EQ(r.events[1].frame, 5);
    EXPECT_EQ(r.events[1].state->settings.camera.position.x, 0.5f);
    EXPECT_EQ(r.events[2].frame, 6);
    EXPECT_EQ(r.events[2].screenshot->samples, 3);
    EXPECT_EQ(r.events[3].frame, 9);
    EXPECT_EQ(r.events[3].state->settings.camera.position.x, 0.0f);

    const fs::path dir =
        fs::temp_directory_path() / ("raylab_session_recorder_test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "s.json").string();
    std::string error;
    ASSERT_TRUE(recorder.save(path, 12, error)) << error;
    SessionRecording read;
    ASSERT_TRUE(loadRecording(path, read, error)) << error;
    EXPECT_EQ(read.frames, 12);
    EXPECT_EQ(read.events, r.events);

    const std::string nothing = (dir / "empty.json").string();
    EXPECT_FALSE(SessionRecorder().save(nothing, 10, error));
    EXPECT_NE(error.find("empty.json"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(nothing));
    fs::remove_all(dir);
}

TEST(SessionReplay, AppliesEventsByFrameAndWaitsAtScreenshots) {
    SessionRecording recording;
    recording.frames = 7;
    recording.events = {{0, stateAt(0.0f), std::nullopt},
                        {2, stateAt(1.0f), std::nullopt},
                        {2, std::nullopt, RecordedScreenshot{4, 0}},
                        {2, stateAt(2.0f), std::nullopt},
                        {5, stateAt(3.0f), std::nullopt}};
    SessionReplay replay(recording);
    EXPECT_EQ(replay.state().settings.camera.position.x, 0.0f); // the first state from the start
    EXPECT_FALSE(replay.advance());                             // frame 0: the first state again
    EXPECT_EQ(replay.frame(), 1);
    EXPECT_FALSE(replay.advance()); // frame 1: nothing
    EXPECT_TRUE(replay.advance());  // frame 2: a state, then the screenshot stops it
    EXPECT_EQ(replay.state().settings.camera.position.x, 1.0f);
    ASSERT_TRUE(replay.pendingScreenshot());
    EXPECT_EQ(replay.pendingScreenshot()->samples, 4);
    EXPECT_EQ(replay.frame(), 2);
    EXPECT_FALSE(replay.advance()); // waits while the screenshot is pending
    EXPECT_EQ(replay.frame(), 2);
    EXPECT_EQ(replay.state().settings.camera.position.x, 1.0f);
    replay.screenshotTaken();
    EXPECT_TRUE(replay.advance()); // the rest of frame 2
    EXPECT_EQ(replay.state().settings.camera.position.x, 2.0f);
    EXPECT_EQ(replay.frame(), 3);
    EXPECT_FALSE(replay.advance());
    EXPECT_FALSE(replay.advance());
    EXPECT_FALSE(replay.finished());
    EXPECT_TRUE(replay.advance()); // frame 5
    EXPECT_EQ(replay.state().settings.camera.position.x, 3.0f);
    EXPECT_FALSE(replay.finished()); // frame 6 of 7 to show
    EXPECT_FALSE(replay.advance());
    EXPECT_TRUE(replay.finished());
}

TEST(SessionState, AWindowsJobSurvivesTheRecording) {
    auto scene = std::make_shared<LoadedScene>();
    scene->source = "meshes/bunny.ply";
    RenderJob job{scene, stateAt(0.25f).settings, true};
    job.settings.samplesPerPixel = 1000;
    job.compare = job.settings;
    job.compare->shadowEpsilon = 0.0f;
    job.divider = 0.375f;
    job.compareMode = CompareMode::Difference;
    job.differenceScale = 0.02f;
    const InspectedPixel inspected{3, 4, Camera{{1.0f, 2.0f, 3.0f}, 5.0f, 6.0f, 50.0f}, 32, 24};
    CameraBookmarks bookmarks;
    bookmarks.slots[8] = Camera{};
    const Camera lab{{0.0f, 0.0f, -2.0f}, 1.0f, 2.0f, 45.0f};

    const RecordedState state = recordedState(job, inspected, lab, bookmarks);
    EXPECT_EQ(state.scene, "meshes/bunny.ply");
    EXPECT_EQ(inspectedPixel(state), inspected);
    EXPECT_EQ(state.labCamera, lab);
    EXPECT_EQ(state.bookmarks, bookmarks);

    const RenderJob back = recordedJob(state, scene, std::nullopt);
    EXPECT_TRUE(sameJob(back, job));
    EXPECT_TRUE(back.keepLinear);
    EXPECT_EQ(back.scene, scene);

    // Waiting for a screenshot: each side stops at its samples.
    const RenderJob capped = recordedJob(state, scene, RecordedScreenshot{5, 7});
    EXPECT_EQ(capped.settings.samplesPerPixel, 5);
    EXPECT_EQ(capped.compare->samplesPerPixel, 7);
    EXPECT_TRUE(samePicture(capped, job)) << "the cap alone does not change the picture";

    RenderSettings shown = job.settings, compare = *job.compare;
    shown.samplesPerPixel = 5;
    compare.samplesPerPixel = 7;
    EXPECT_TRUE(isScreenshotPicture(shown, compare, false, {5, 7}));
    EXPECT_FALSE(isScreenshotPicture(shown, compare, true, {5, 7})) << "a preview";
    EXPECT_FALSE(isScreenshotPicture(shown, compare, false, {5, 6}));
    EXPECT_FALSE(isScreenshotPicture(shown, std::nullopt, false, {5, 7}));
    EXPECT_TRUE(isScreenshotPicture(shown, std::nullopt, false, {5, 0}));

    const RecordedState plain = recordedState(RenderJob{scene, job.settings}, std::nullopt,
                                              std::nullopt, CameraBookmarks{});
    EXPECT_FALSE(plain.compare);
    EXPECT_FALSE(plain.inspected);
    EXPECT_FALSE(recordedJob(plain, scene, std::nullopt).compare);
}

} // namespace
} // namespace raylab::viewer
