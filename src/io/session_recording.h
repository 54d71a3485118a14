#pragma once
// A recorded viewer session (raylab --record FILE.json, played back by --replay FILE.json): what
// the window asked the tracer for and did with the pictures, frame by frame. Two kinds of event,
// each with the frame (the count of frames the window had shown) at which it happened:
//   - a state: everything that decides the picture and the files a screenshot writes (the
//     scene, the render job's settings with the render size and sample cap, the split, the
//     inspected pixel, the observer view's lab camera, the camera bookmarks), written whole
//     whenever any of it changes, so any state can be applied without the ones before it;
//   - a screenshot: the samples per pixel of the picture it saved (of each side of a split).
// Pictures are exact sums of per-pixel samples, so a picture of the same job with the same
// samples has the same bytes, however the passes fell: that is what makes a replay's screenshots
// equal to the recording's.
//
// The file:
//   {"raylab_recording": 1, "frames": 240,
//    "events": [
//      {"frame": 0, "state": {
//          "settings": {<settings_json.h, with "scene", and "bookmarks" and "observer" when set>},
//          "compare": {<settings>}, "split": {"divider": 0.5, "mode": "wipe",
//                                             "difference_scale": 0.1},
//          "inspected": {"pixel": [250, 400],
//                        "picture": {"camera": {...}, "image": {"width": 500, ...}}}}},
//      {"frame": 31, "screenshot": {"samples": 12, "compare_samples": 12}}]}
// "compare" and "split" only for a split picture ("compare_samples" likewise), "inspected" only
// when a pixel is inspected (its "picture" read over the state's settings). "frames": the frames
// the session showed in all. Frames never decrease along the events.

#include "core/render_settings.h"
#include "io/settings_json.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab {

// The pixel looked inside, with the camera and picture size it was picked in.
struct RecordedInspection {
    int x = 0, y = 0;
    Camera camera;
    int width = 0, height = 0;
    bool operator==(const RecordedInspection&) const = default;
};

struct RecordedState {
    std::string scene;       // the scene's source: the built-in box's name or a mesh path
    RenderSettings settings; // the job's: width and height the render size, samples the cap
    // A split picture: the right side's settings, the fraction of the width shown from the left,
    // and whether it shows the signed difference (at differenceScale W/m^2 in full colour).
    std::optional<RenderSettings> compare;
    float divider = 0.5f;
    bool difference = false;
    float differenceScale = 0.1f;
    std::optional<RecordedInspection> inspected;
    std::optional<Camera> labCamera; // the observer view: the lab's camera, kept
    CameraBookmarks bookmarks;
    bool operator==(const RecordedState&) const = default;
};

struct RecordedScreenshot {
    int samples = 0;        // of the picture (its left side when split)
    int compareSamples = 0; // of a split's right side; 0 when not split
    bool operator==(const RecordedScreenshot&) const = default;
};

struct RecordedEvent {
    long frame = 0;
    std::optional<RecordedState> state; // exactly one of state and screenshot
    std::optional<RecordedScreenshot> screenshot;
    bool operator==(const RecordedEvent&) const = default;
};

struct SessionRecording {
    long frames = 0; // shown in all
    std::vector<RecordedEvent> events;
    bool operator==(const SessionRecording&) const = default;
};

// The most events a recording may hold (an hour of dragging at 60 frames a second is 216,000).
inline constexpr std::size_t kMaxRecordedEvents = 1000000;

std::string recordingToJson(const SessionRecording& recording);
// Reads a recording; false with a one-line error naming the event and key. Every settings object
// must pass validate(), frames must not decrease and may not exceed "frames", and the first event
// must be a state.
bool recordingFromJson(const std::string& text, SessionRecording& recording, std::string& error);

// Errors start with the path. Saving is atomic (a temporary file and a rename).
bool loadRecording(const std::string& path, SessionRecording& recording, std::string& error);
bool saveRecording(const std::string& path, const SessionRecording& recording, std::string& error);

} // namespace raylab
