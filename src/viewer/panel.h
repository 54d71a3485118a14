#pragma once
// The Dear ImGui panel: light, light transport (integrator, bounces, the lab's N against the
// computed one), indirect term and shadows, camera, display, statistics and scene.
// It fills the column at the window's left edge that the layout gives it (view_layout.h), the
// window's height, beside the picture; dragging its right edge makes it wider or narrower. The
// screenshot button comes first, at a fixed place, so scripts can click it. Widgets edit a copy
// of the settings that is accepted only when valid (settings_edit.h).

#include "core/integrators/pixel_inspection.h"
#include "core/render_settings.h"
#include "difference_view.h"
#include "file_browser.h"
#include "inspected_pixel.h"
#include "io/settings_json.h"
#include "panel_numbers.h"
#include "pixel_readout.h"
#include "scene_loader.h"
#include "view_layout.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace raylab::viewer {

// What the panel edits.
struct PanelState {
    RenderSettings settings;      // the current settings, always valid
    float resolutionScale = 1.0f; // render resolution = framebuffer size * this, in [0.1, 1]
    // The A/B split: left of the divider these settings, right of it the same with the other
    // integrator (splitCompare, split_view.h); divider: the fraction of the width on the left.
    bool split = false;
    float divider = 0.5f;
    // How the split shows its sides (M switches): a wipe at the divider, or the signed difference
    // left - right (live - A) with differenceScale (W/m^2) in full colour.
    CompareMode compareMode = CompareMode::Wipe;
    float differenceScale = kDefaultDifferenceScale;
    // Snapshot A (K, or the panel's button): settings kept to compare with. With compareSnapshot
    // the split's right side shows A instead of the other integrator (splitCompare).
    std::optional<RenderSettings> snapshot;
    bool compareSnapshot = false;
    CameraBookmarks bookmarks; // Ctrl+1..9 stores the camera, 1..9 returns to it
    // The pixel looked inside (Ctrl+click); its numbers are PanelView's.
    std::optional<InspectedPixel> inspected;
    std::string scenePath; // the path field
    bool browsing = false; // the file browser is open below the path field ("Browse")
    FileBrowser browser;
    std::string refused; // why the last edit was refused; empty when it was not
    std::string status;  // the last screenshot or scene-load message
    bool statusIsError = false;
};

// What the panel shows but does not edit.
struct PanelView {
    // The panel's column in Dear ImGui units: its width (its height is the display's) and the
    // widths a drag of its right edge may give it.
    float width = kPanelColumnWidth;
    float minWidth = kMinPanelColumnWidth;
    float maxWidth = kPanelColumnWidth;
    std::string sceneName;
    std::size_t triangles = 0;
    std::optional<LoadProgress> loading; // the scene load running in the background, if any
    float step = 0.1f;                   // navigationStep of the scene: drag speeds
    float maxEpsilon = 0.1f;             // the right end of the epsilon slider
    bool hasEmitters = false;            // the scene has emitting triangles (their scale is shown)
    // The observer view is on (observer_view.h): the camera section shows and moves the observer.
    bool observer = false;
    // The inspected pixel's numbers (core's inspectPixel), when a pixel is inspected.
    const PixelInspection* inspection = nullptr;
    // The pixel under the cursor and the Shift + drag rectangle's mean (picture_readouts.h).
    const PixelReadout* hover = nullptr;
    const RectangleMean* rectangle = nullptr;
    // The statistics shown: a copy refreshed a few times a second (panel_layer.h), so that
    // an untouched panel draws the same pixels from frame to frame. Null: none shown.
    const PanelNumbers* numbers = nullptr;
};

struct PanelActions {
    bool screenshot = false;
    bool frameScene = false;
    bool resetToLab = false;
    bool openScene = false;       // load PanelState::scenePath (replaces a running load)
    bool cancelLoad = false;      // cancel the running load
    bool useMeanIndirect = false; // set the lab's N to the path-traced picture's mean N
    bool keepSnapshot = false;    // keep the current settings as snapshot A
    bool toggleObserver = false;  // the observer view on / off
    float resizedTo = 0.0f;       // > 0: its edge was dragged; the width it has now (units)
};

// Draws the panel for this ImGui frame.
PanelActions drawPanel(PanelState& state, const PanelView& view);

} // namespace raylab::viewer
