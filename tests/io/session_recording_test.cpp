// Session recordings (--record / --replay): every part of a state and a screenshot survives a
// write and a read bit for bit, and each kind of bad recording is refused with a line naming
// the event and the key.

#include "io/session_recording.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <unistd.h>

namespace raylab {
namespace {

namespace fs = std::filesystem;

RecordedState boxState() {
    RecordedState state;
    state.scene = "cornell";
    state.settings.width = 320;
    state.settings.height = 240;
    state.settings.samplesPerPixel = 4096;
    return state;
}

// A session with a state of every optional part, odd floats included.
SessionRecording fullSession() {
    SessionRecording recording;
    recording.frames = 90;
    recording.events.push_back({0, boxState(), std::nullopt});
    RecordedState moved = boxState();
    moved.settings.camera.position = {0.1f, -0.2f, -2.7f};
    moved.settings.camera.yawDegrees = 12.345678f;
    moved.settings.shadowEpsilon = 0.0f;
    moved.settings.view = View::Direct;
    moved.compare = moved.settings;
    moved.compare->indirectIntensity = 0.3f;
    moved.divider = 0.3f;
    moved.difference = true;
    moved.differenceScale = 0.05f;
    moved.inspected =
        RecordedInspection{17, 103, Camera{{0.0f, 0.3f, -3.0f}, 1.5f, -2.0f, 40.0f}, 160, 120};
    moved.labCamera = Camera{{0.5f, 0.5f, -1.0f}, 10.0f, 5.0f, 53.0f};
    moved.bookmarks.slots[3] = Camera{{1.0f, 2.0f, 3.0f}, 4.0f, 5.0f, 60.0f};
    recording.events.push_back({12, moved, std::nullopt});
    recording.events.push_back({40, std::nullopt, RecordedScreenshot{7, 9}});
    RecordedState mesh = boxState();
    mesh.scene = "/tmp/some mesh.obj";
    recording.events.push_back({40, mesh, std::nullopt});
    recording.events.push_back({88, std::nullopt, RecordedScreenshot{16, 0}});
    return recording;
}

TEST(SessionRecording, EveryPartRoundTripsExactly) {
    const SessionRecording written = fullSession();
    SessionRecording read;
    std::string error;
    ASSERT_TRUE(recordingFromJson(recordingToJson(written), read, error)) << error;
    EXPECT_EQ(read, written);
    // The floats themselves, bit for bit (operator== on floats already says so; this names one).
    EXPECT_EQ(read.events[1].state->settings.camera.yawDegrees, 12.345678f);
    EXPECT_EQ(read.events[1].state->differenceScale, 0.05f);
    EXPECT_EQ(read.events[1].state->inspected->camera.verticalFovDegrees, 40.0f);
}

TEST(SessionRecording, SavesAtomicallyAndLoads) {
    const fs::path dir =
        fs::temp_directory_path() / ("raylab_session_recording_test-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "session.json").string();
    std::string error;
    ASSERT_TRUE(saveRecording(path, fullSession(), error)) << error;
    SessionRecording read;
    ASSERT_TRUE(loadRecording(path, read, error)) << error;
    EXPECT_EQ(read, fullSession());
    // Nothing but the file is left in the folder.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    EXPECT_FALSE(saveRecording((dir / "missing" / "x.json").string(), fullSession(), error));
    EXPECT_NE(error.find("missing"), std::string::npos) << error;
    EXPECT_FALSE(loadRecording((dir / "none.json").string(), read, error));
    EXPECT_NE(error.find("none.json"), std::string::npos) << error;
    EXPECT_FALSE(loadRecording(dir.string(), read, error)) << "a folder is not a recording";
    fs::remove_all(dir);
}

// The error for `text`, which must be refused.
std::string refusal(const std::string& text) {
    SessionRecording recording = fullSession();
    const SessionRecording before = recording;
    std::string error;
    EXPECT_FALSE(recordingFromJson(text, recording, error)) << text;
    EXPECT_EQ(recording, before) << "a refused recording changed the output";
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    return error;
}

std::string withEvents(const std::string& events, long frames = 10) {
    return "{\"raylab_recording\": 1, \"frames\": " + std::to_string(frames) + ", \"events\": [" +
           events + "]}";
}

const std::string kState =
    R"({"frame": 0, "state": {"settings": {"scene": "cornell", "image": {"width": 8, "height": 8}}}})";

TEST(SessionRecording, ReadsAMinimalRecording) {
    SessionRecording recording;
    std::string error;
    ASSERT_TRUE(recordingFromJson(
        withEvents(kState + R"(, {"frame": 3, "screenshot": {"samples": 2}})"), recording, error))
        << error;
    ASSERT_EQ(recording.events.size(), 2u);
    EXPECT_EQ(recording.events[0].state->settings.width, 8);
    EXPECT_EQ(recording.events[0].state->settings.camera, RenderSettings{}.camera);
    EXPECT_EQ(recording.events[1].screenshot->samples, 2);
}

TEST(SessionRecording, RefusesBadRecordingsNamingWhere) {
    EXPECT_NE(refusal("{").find("invalid JSON"), std::string::npos);
    EXPECT_NE(refusal("[]").find("object"), std::string::npos);
    EXPECT_NE(refusal(R"({"raylab_recording": 2, "frames": 1, "events": []})").find("version"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents("")).find("events"), std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 0, "screenshot": {"samples": 1}})"))
                  .find("first event must be a state"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(kState + R"(, {"frame": 11, "screenshot": {"samples": 1}})"))
                  .find("events[1].frame"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 5, "state": {"settings": {"scene": "cornell"}}},
                                    {"frame": 4, "screenshot": {"samples": 1}})"))
                  .find("events[1].frame"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(kState + R"(, {"frame": 1, "screenshot": {"samples": 0}})"))
                  .find("events[1].screenshot.samples"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(kState + R"(, {"frame": 1, "screenshot": {"samples": 1,
                                             "compare_samples": 1}})"))
                  .find("only for a split"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 0, "state": {"settings": {"image": {"width": 8}}}})"))
                  .find("events[0].state.settings.scene"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 0, "state": {"settings": {"scene": "cornell",
                                    "camera": {"fov": 200}}}})"))
                  .find("events[0].state.settings"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 0, "state": {"settings": {"scene": "cornell"},
                                    "colour": 1}})"))
                  .find("state.colour: unknown key"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 0, "state": {"settings": {"scene": "cornell"},
                                    "compare": {}}})"))
                  .find("come together"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 0, "state": {"settings": {"scene": "cornell"},
                                    "compare": {}, "split": {"divider": 2, "mode": "wipe",
                                    "difference_scale": 1}}})"))
                  .find("state.split.divider"),
              std::string::npos);
    EXPECT_NE(refusal(withEvents(R"({"frame": 0, "state": {"settings": {"scene": "cornell",
                                    "image": {"width": 8, "height": 8}},
                                    "inspected": {"pixel": [8, 0], "picture": {}}}})"))
                  .find("outside the picture"),
              std::string::npos);
}

} // namespace
} // namespace raylab
