#include "panel.h"

#include "core/camera.h"
#include "core/lab_presets.h"
#include "core/render/false_colour.h"
#include "panel_browser.h"
#include "settings_edit.h"
#include "split_view.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <iterator>
#include <string>
#include <thread>

namespace raylab::viewer {

namespace {

const ImVec4 kRed(1.0f, 0.45f, 0.4f, 1.0f);
const ImVec4 kGreen(0.55f, 0.9f, 0.55f, 1.0f);

// A colour swatch that opens a picker; components stay in [0, 1].
bool colourButton(const char* id, glm::vec3& colour) {
    return ImGui::ColorEdit3(id, &colour.x,
                             ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_NoLabel |
                                 ImGuiColorEditFlags_Float);
}

// A size given for Dear ImGui's default 13-pixel font, at the font's size (the UI scale's).
float atFontSize(float pixels) { return pixels / 13.0f * ImGui::GetFontSize(); }

// Two widgets on one row: each gets half of the item width.
float halfWidth() { return 0.5f * (ImGui::CalcItemWidth() - ImGui::GetStyle().ItemInnerSpacing.x); }

void lightSection(RenderSettings& edit, const PanelView& view) {
    if (!ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    ImGui::DragFloat3("position##light", &edit.light.position.x, 0.1f * view.step, 0.0f, 0.0f,
                      "%.3f");
    colourButton("##light colour", edit.light.color);
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() -
                            ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::DragFloat("power (W)", &edit.light.intensity,
                     0.01f * std::max(edit.light.intensity, 1.0f), 0.0f, FLT_MAX, "%.3f",
                     ImGuiSliderFlags_AlwaysClamp);
    ImGui::DragFloat("radius", &edit.light.radius, 0.01f * view.step, 0.0f, FLT_MAX,
                     edit.light.radius == 0.0f ? "0 (a point)" : "%.4f");
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("a sphere of the same power: soft shadows (0 is the lab's point light)");
    }
    if (view.hasEmitters) {
        ImGui::DragFloat("emitters x", &edit.emissionScale, 0.01f, 0.0f, FLT_MAX, "%.3f");
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip("scales the emission of the scene's emitting triangles");
        }
    }
}

// The integrator, its bounces and sampler, and "the lab's N for this scene": the path-traced
// picture's mean N beside the constant, and a button (or N) that makes it the constant.
void lightTransportSection(RenderSettings& edit, PanelState& state, const PanelView& view,
                           PanelActions& actions) {
    if (!ImGui::CollapsingHeader("Light transport", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    const float inner = ImGui::GetStyle().ItemInnerSpacing.x;
    const float half = halfWidth();
    int integrator = edit.integrator == Integrator::Lab ? 0 : 1;
    ImGui::SetNextItemWidth(half);
    if (ImGui::Combo("##integrator", &integrator, "lab: constant N\0path traced N\0")) {
        edit.integrator = integrator == 0 ? Integrator::Lab : Integrator::Path;
    }
    ImGui::SameLine(0.0f, inner);
    int sampler = edit.sampler == SamplerKind::Sobol ? 0 : 1;
    ImGui::SetNextItemWidth(half);
    if (ImGui::Combo("integrator", &sampler, "Sobol\0independent\0")) {
        edit.sampler = sampler == 0 ? SamplerKind::Sobol : SamplerKind::Independent;
    }
    ImGui::Checkbox("A/B split (B); hold F for the right side", &state.split);
    if (ImGui::Button("Keep as A (K)")) {
        actions.keepSnapshot = true;
    }
    ImGui::SameLine(0.0f, inner);
    ImGui::BeginDisabled(!state.snapshot);
    int right = state.compareSnapshot && state.snapshot ? 1 : 0;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
    if (ImGui::Combo("##right side", &right, "right: the other integrator\0right: A\0")) {
        state.compareSnapshot = right == 1;
    }
    ImGui::EndDisabled();
    if (state.split) {
        int mode = state.compareMode == CompareMode::Difference ? 1 : 0;
        if (ImGui::Combo("compare (M)", &mode, "wipe\0difference\0")) {
            state.compareMode = mode == 1 ? CompareMode::Difference : CompareMode::Wipe;
        }
        if (state.compareMode == CompareMode::Difference) {
            ImGui::SliderFloat("full colour", &state.differenceScale, kMinDifferenceScale,
                               kMaxDifferenceScale, "%.4g W/m2",
                               ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
            ImGui::TextUnformatted("showing: left - right (red > 0, blue < 0)");
        } else {
            ImGui::SliderFloat("divider", &state.divider, 0.0f, 1.0f, "%.2f",
                               ImGuiSliderFlags_AlwaysClamp);
            ImGui::TextUnformatted("showing: a wipe (hold F: a flip to the right)");
        }
        if (state.compareSnapshot && state.snapshot) {
            const std::vector<std::string> differences =
                settingsDifferences(edit, splitCompare(edit, &*state.snapshot));
            ImGui::TextUnformatted(differences.empty() ? "left (live) and right (A): the same"
                                                       : "left (live) -> right (A):");
            for (const std::string& line : differences) {
                ImGui::BulletText("%s", line.c_str());
            }
        }
    }
    ImGui::BeginDisabled(edit.integrator != Integrator::Path && !state.split);
    ImGui::InputInt("max bounces", &edit.maxBounces);
    const PictureFacts* picture = view.numbers ? &view.numbers->picture : nullptr;
    if (picture && picture->pathTraced && picture->samples > 0) {
        const glm::vec3 n = picture->meanIndirect;
        const glm::vec3 lab = edit.indirect3();
        ImGui::Text("mean N %.3f %.3f %.3f", static_cast<double>(n.x), static_cast<double>(n.y),
                    static_cast<double>(n.z));
        ImGui::Text("lab's N %.3f %.3f %.3f", static_cast<double>(lab.x),
                    static_cast<double>(lab.y), static_cast<double>(lab.z));
    } else {
        ImGui::TextDisabled("mean N: when a path-traced picture is shown");
    }
    if (ImGui::Button("Use the mean N as the lab's N (N)")) {
        actions.useMeanIndirect = true;
    }
    ImGui::EndDisabled();
}

void indirectAndShadowSection(RenderSettings& edit, const PanelView& view) {
    if (!ImGui::CollapsingHeader("Indirect light and shadows", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    const float inner = ImGui::GetStyle().ItemInnerSpacing.x;
    ImGui::Checkbox("##indirect on", &edit.indirect);
    ImGui::SameLine(0.0f, inner);
    ImGui::BeginDisabled(!edit.indirect);
    colourButton("##indirect colour", edit.indirectColor);
    ImGui::SameLine(0.0f, inner);
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - 2.0f * (ImGui::GetFrameHeight() + inner));
    ImGui::DragFloat("indirect", &edit.indirectIntensity, 0.005f, 0.0f, FLT_MAX, "%.3f",
                     ImGuiSliderFlags_AlwaysClamp);
    ImGui::EndDisabled();

    ImGui::Checkbox("##shadows on", &edit.shadows);
    ImGui::SameLine(0.0f, inner);
    ImGui::BeginDisabled(!edit.shadows);
    // Logarithmic over six decades; the leftmost position is exactly 0 (the lab's acne).
    float t = sliderFromEpsilon(edit.shadowEpsilon, view.maxEpsilon);
    char shown[32];
    if (edit.shadowEpsilon > 0.0f) {
        std::snprintf(shown, sizeof shown, "%.2e", static_cast<double>(edit.shadowEpsilon));
    } else {
        std::snprintf(shown, sizeof shown, "0 (acne)");
    }
    ImGui::SetNextItemWidth(ImGui::CalcItemWidth() - ImGui::GetFrameHeight() - inner);
    if (ImGui::SliderFloat("shadow eps", &t, 0.0f, 1.0f, shown, ImGuiSliderFlags_NoInput)) {
        edit.shadowEpsilon = epsilonFromSlider(t, view.maxEpsilon);
    }
    ImGui::InputFloat("eps (type)", &edit.shadowEpsilon, 0.0f, 0.0f, "%.3e");
    ImGui::EndDisabled();
}

void cameraSection(RenderSettings& edit, const PanelView& view, PanelActions& actions) {
    if (!ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    bool observer = view.observer;
    if (ImGui::Checkbox("observer view (O)", &observer)) {
        actions.toggleObserver = true;
    }
    ImGui::SameLine();
    ImGui::TextDisabled(view.observer ? "moving the observer; the lab camera is kept"
                                      : "moving the lab camera");
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("the keys, drags, orbit, these fields, undo and bookmarks move this "
                          "camera");
    }
    const float inner = ImGui::GetStyle().ItemInnerSpacing.x;
    ImGui::DragFloat3("position##camera", &edit.camera.position.x, 0.1f * view.step, 0.0f, 0.0f,
                      "%.3f");
    const float half = halfWidth();
    ImGui::SetNextItemWidth(half);
    ImGui::DragFloat("##yaw", &edit.camera.yawDegrees, 0.25f, -180.0f, 180.0f, "yaw %.2f",
                     ImGuiSliderFlags_AlwaysClamp);
    ImGui::SameLine(0.0f, inner);
    ImGui::SetNextItemWidth(half);
    ImGui::SliderFloat("yaw, pitch", &edit.camera.pitchDegrees, -89.0f, 89.0f, "pitch %.2f",
                       ImGuiSliderFlags_AlwaysClamp);
    ImGui::SetNextItemWidth(half);
    ImGui::SliderFloat("##fov", &edit.camera.verticalFovDegrees, 1.0f, 179.0f, "%.2f deg");
    ImGui::SameLine(0.0f, inner);
    ImGui::Text("f = %.1f px", static_cast<double>(
                                   focalLengthPixels(edit.camera.verticalFovDegrees, edit.height)));
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("vertical field of view and the focal length it gives at the render "
                          "height of %d px",
                          edit.height);
    }
    ImGui::TextDisabled("left drag turns, right drag orbits, middle drag pans");
    if (ImGui::Button("Frame the scene")) {
        actions.frameScene = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Reset to the lab's defaults")) {
        actions.resetToLab = true;
    }
}

// The false-colour scale as a row of swatches, each labelled with the value (W/m^2) where its
// colour starts: every 2 stops from the dark end to the bright end.
void falseColourLegend(float exposure) {
    constexpr int kSwatches = 9;
    const float width = ImGui::GetContentRegionAvail().x / static_cast<float>(kSwatches);
    for (int i = 0; i < kSwatches; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(kSwatches - 1);
        const std::array<uint8_t, 3> c = falseColourAt(t);
        if (i > 0) {
            ImGui::SameLine(0.0f, 0.0f);
        }
        ImGui::ColorButton(("##fc" + std::to_string(i)).c_str(),
                           ImVec4(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1.0f),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(width, ImGui::GetFrameHeight()));
    }
    ImGui::Text("%.3g", static_cast<double>(falseColourValue(0.0f, exposure)));
    ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.45f);
    ImGui::Text("%.3g", static_cast<double>(falseColourValue(0.5f, exposure)));
    ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.85f);
    ImGui::Text("%.3g W/m2", static_cast<double>(falseColourValue(1.0f, exposure)));
}

void displaySection(RenderSettings& edit, PanelState& state) {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    const float inner = ImGui::GetStyle().ItemInnerSpacing.x;
    const float half = halfWidth();
    constexpr DisplayMode kModes[] = {DisplayMode::Lab, DisplayMode::Srgb,
                                      DisplayMode::FalseColour};
    int mode = static_cast<int>(std::find(std::begin(kModes), std::end(kModes), edit.display) -
                                std::begin(kModes));
    ImGui::SetNextItemWidth(half);
    if (ImGui::Combo("##display", &mode, "lab clamp\0sRGB\0false colour\0")) {
        edit.display = kModes[mode];
    }
    ImGui::SameLine(0.0f, inner);
    ImGui::BeginDisabled(edit.display == DisplayMode::Lab);
    ImGui::SetNextItemWidth(half);
    ImGui::SliderFloat("display, EV", &edit.exposure, -10.0f, 10.0f, "%.2f EV",
                       ImGuiSliderFlags_AlwaysClamp);
    ImGui::EndDisabled();
    if (edit.display == DisplayMode::FalseColour) {
        falseColourLegend(edit.exposure);
    }
    ImGui::SliderFloat("resolution", &state.resolutionScale, 0.1f, 1.0f, "x %.2f",
                       ImGuiSliderFlags_AlwaysClamp);
    ImGui::SetNextItemWidth(half);
    ImGui::SliderInt("##cap", &edit.samplesPerPixel, 1, 4096, "cap %d",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    ImGui::SameLine(0.0f, inner);
    const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    ImGui::SetNextItemWidth(half);
    ImGui::SliderInt("samples, threads", &edit.threads, 0, hardware,
                     edit.threads == 0 ? "all threads" : "%d threads",
                     ImGuiSliderFlags_AlwaysClamp);
}

// What the picture shows (a term of the equation, or the lit picture) and the lab's steps.
void viewSection(RenderSettings& edit) {
    if (!ImGui::CollapsingHeader("View and the lab's steps", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    static constexpr View kViews[] = {View::Beauty,     View::Albedo, View::Direct, View::Indirect,
                                      View::Visibility, View::Normal, View::Depth,  View::Cost};
    if (ImGui::BeginCombo("view (V)", toString(edit.view))) {
        for (const View v : kViews) {
            if (ImGui::Selectable(toString(v), v == edit.view)) {
                edit.view = v;
            }
        }
        ImGui::EndCombo();
    }
    if (ImGui::BeginCombo("lab step", "set the lab's step...")) {
        for (const LabPreset& preset : labPresets()) {
            const std::string name(preset.name);
            if (ImGui::Selectable(name.c_str())) {
                preset.apply(edit);
            }
            if (ImGui::IsItemHovered()) {
                ImGui::SetTooltip("%s\n%s", std::string(preset.shows).c_str(),
                                  std::string(preset.equation).c_str());
            }
        }
        ImGui::EndCombo();
    }
}

// The inspected pixel: the lab's equation with its numbers (Ctrl+click a pixel).
void inspectorSection(const PanelView& view) {
    if (!ImGui::CollapsingHeader("Inside a pixel (Ctrl+click)", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    if (view.inspection == nullptr) {
        ImGui::TextDisabled("Ctrl+click the picture to look inside a pixel");
        return;
    }
    const PixelInspection& p = *view.inspection;
    const auto v3 = [](const char* label, const glm::vec3& v) {
        ImGui::Text("%s %.4g %.4g %.4g", label, static_cast<double>(v.x), static_cast<double>(v.y),
                    static_cast<double>(v.z));
    };
    ImGui::Text("pixel %d, %d", p.x, p.y);
    if (!p.hit) {
        ImGui::TextUnformatted("the ray hits nothing: R = 0");
        return;
    }
    ImGui::Text("triangle %u (material %u) at t = %.4g", p.triangle, p.material,
                static_cast<double>(p.t));
    v3("point", p.point);
    v3("rho", p.rho);
    v3("n (facing the ray)", p.normal);
    v3("r (to the light)", p.toLight);
    ImGui::Text("|r| = %.4g, r.n = %.4g", static_cast<double>(p.distance),
                static_cast<double>(p.cosTheta));
    if (p.blocker) {
        ImGui::Text("shadow ray blocked by triangle %u at t = %.3g (eps %.3g < t < %.4g)",
                    p.blocker->triangle, static_cast<double>(p.blocker->t),
                    static_cast<double>(p.shadowEpsilon), static_cast<double>(p.shadowTMax));
    } else {
        ImGui::Text("shadow ray %s", p.shadowTested ? "clear" : "not traced");
    }
    v3("D", p.direct);
    v3("N", p.indirect);
    if (p.emitted != glm::vec3(0.0f)) {
        v3("E", p.emitted);
    }
    v3("R = E + rho (D + N)", p.radiance);
    ImGui::Text("shown %d %d %d", p.display[0], p.display[1], p.display[2]);
    if (!p.path.empty()) {
        ImGui::Text("one path, %zu surfaces:", p.path.size());
        for (std::size_t i = 0; i < p.path.size(); ++i) {
            const PathVertexRecord& vertex = p.path[i];
            ImGui::Text(" %zu: D %.3g %.3g %.3g adds %.3g %.3g %.3g", i,
                        static_cast<double>(vertex.direct.x), static_cast<double>(vertex.direct.y),
                        static_cast<double>(vertex.direct.z), static_cast<double>(vertex.adds.x),
                        static_cast<double>(vertex.adds.y), static_cast<double>(vertex.adds.z));
        }
    }
}

// The pixel under the cursor and the rectangle dragged with Shift: linear values (the film's
// mean, or in the split's difference the signed difference) and the bytes shown.
void readoutSection(const PanelState& state, const PanelView& view) {
    if (!ImGui::CollapsingHeader("Under the cursor", ImGuiTreeNodeFlags_DefaultOpen)) {
        return;
    }
    const char* value =
        state.split && state.compareMode == CompareMode::Difference ? "left - right" : "R";
    if (const PixelReadout* h = view.hover) {
        ImGui::Text("pixel %d, %d: %s %.4g %.4g %.4g", h->x, h->y, value,
                    static_cast<double>(h->linear.x), static_cast<double>(h->linear.y),
                    static_cast<double>(h->linear.z));
        ImGui::Text("shown %d %d %d", h->display[0], h->display[1], h->display[2]);
    } else {
        ImGui::TextDisabled("point at the picture to read a pixel");
    }
    if (const RectangleMean* r = view.rectangle) {
        ImGui::Text("%d,%d - %d,%d (%ld px)", r->rectangle.x0, r->rectangle.y0, r->rectangle.x1,
                    r->rectangle.y1, r->pixels);
        ImGui::Text("mean %s %.4g %.4g %.4g", value, r->mean.x, r->mean.y, r->mean.z);
    }
}

void statisticsSection(const PanelView& view) {
    if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen) ||
        view.numbers == nullptr) {
        return;
    }
    const PanelNumbers& n = *view.numbers;
    // Frames are drawn only when something changed, so the rate is that of the redraws.
    const float frameMs = n.frameMs.mean();
    ImGui::Text("window %.0f redraws/s, %.1f ms each; upload %.2f ms",
                frameMs > 0.0f ? 1000.0 / static_cast<double>(frameMs) : 0.0,
                static_cast<double>(n.drawMs.mean()), n.uploadMs);
    if (const PictureFacts& p = n.picture; p.width > 0) {
        ImGui::Text("%d x %d, %d samples%s, %zu triangles", p.width, p.height, p.samples,
                    p.preview ? " (preview)" : (p.final ? ": converged (cap reached)" : ""),
                    view.triangles);
        ImGui::Text("pass %.1f ms, %.2f Mrays/s, %.2f Msamples/s", p.passMs, p.raysPerSecond * 1e-6,
                    p.samplesPerSecond * 1e-6);
        if (p.noisePercent >= 0.0) {
            ImGui::Text("noise %.2f%% (relative standard error)", p.noisePercent);
        }
    }
    if (n.noisePercent.count() > 0) {
        ImGui::PlotLines("##noise", n.noisePercent.data(), n.noisePercent.size(),
                         n.noisePercent.offset(), "noise %", 0.0f, FLT_MAX,
                         ImVec2(ImGui::CalcItemWidth(), atFontSize(32.0f)));
        ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::TextUnformatted("noise");
    }
    const float half = halfWidth();
    ImGui::PlotLines("##pass", n.passMs.data(), n.passMs.size(), n.passMs.offset(), "pass ms", 0.0f,
                     FLT_MAX, ImVec2(half, atFontSize(32.0f)));
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::PlotLines("##draw", n.drawMs.data(), n.drawMs.size(), n.drawMs.offset(), "draw ms", 0.0f,
                     FLT_MAX, ImVec2(half, atFontSize(32.0f)));
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextUnformatted("times");
}

// The path field and its Open button, on one row at a fixed place (scripts click the field),
// then the scene shown.
void sceneRow(PanelState& state, const PanelView& view, PanelActions& actions) {
    const float openWidth =
        ImGui::CalcTextSize("Loading...").x + 2.0f * ImGui::GetStyle().FramePadding.x;
    ImGui::SetNextItemWidth(-(openWidth + ImGui::GetStyle().ItemInnerSpacing.x));
    const bool enter =
        ImGui::InputText("##path", &state.scenePath, ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("a mesh file (OBJ, PLY, glTF, ...) or cornell; Return opens it");
    }
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    if (ImGui::Button("Open", ImVec2(openWidth, 0.0f)) || enter) {
        actions.openScene = true;
    }
    if (ImGui::Button(state.browsing ? "Close browser" : "Browse...")) {
        state.browsing = !state.browsing;
        if (state.browsing && !state.browser.open(FileBrowser::startFolder(state.scenePath))) {
            state.browser.open(FileBrowser::startFolder(""));
        }
    }
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("pick a mesh file from a list of folders and mesh files");
    }
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextWrapped("scene: %s", view.sceneName.c_str());
    if (state.browsing) {
        std::string chosen;
        if (drawFileBrowser(state.browser, chosen)) {
            state.scenePath = chosen;
            state.browsing = false;
            actions.openScene = true;
        }
    }
    if (view.loading) {
        if (ImGui::Button("Cancel (Esc)")) {
            actions.cancelLoad = true;
        }
        ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::TextWrapped("loading %s  %.1f s", view.loading->source.c_str(),
                           view.loading->seconds);
    }
}

} // namespace

PanelActions drawPanel(PanelState& state, const PanelView& view) {
    PanelActions actions;
    const ImGuiIO& io = ImGui::GetIO();
    // The column: the left edge, the display's height, the width given; only the right edge
    // moves (a drag on it is read back below). Opaque, with square corners and no border: it is
    // the window's side, not a window over the picture. The window leaves the column's last unit
    // (a dark line between panel and picture) to the anti-aliased fringe of its resize grip,
    // which would otherwise reach the picture's first pixel column.
    const float height = io.DisplaySize.y;
    const float width = view.width - 1.0f;
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(view.minWidth, view.width) - 1.0f, height),
                                        ImVec2(std::max(view.maxWidth, view.width) - 1.0f, height));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImVec4 background = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    background.w = 1.0f;
    ImGui::PushStyleColor(ImGuiCol_WindowBg, background);
    ImGui::Begin("raylab", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    ImGui::PopStyleColor();
    ImGui::PopStyleVar(2);
    if (const float now = ImGui::GetWindowWidth(); std::abs(now - std::floor(width)) >= 1.0f) {
        actions.resizedTo = now + 1.0f;
    }
    ImGui::PushItemWidth(-atFontSize(110.0f)); // room for the labels

    // First, so their places are fixed: scripts click the button at (100, 17) (at UI scale 1)
    // and the path field below it.
    if (ImGui::Button("Save screenshot (F12)", ImVec2(-1.0f, 0.0f))) {
        actions.screenshot = true;
    }
    sceneRow(state, view, actions);
    if (!state.status.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, state.statusIsError ? kRed : kGreen);
        ImGui::TextWrapped("%s", state.status.c_str());
        ImGui::PopStyleColor();
    }

    statisticsSection(view);
    RenderSettings edit = state.settings;
    inspectorSection(view);
    readoutSection(state, view);
    lightSection(edit, view);
    lightTransportSection(edit, state, view, actions);
    viewSection(edit);
    indirectAndShadowSection(edit, view);
    cameraSection(edit, view, actions);
    displaySection(edit, state);
    if (!(edit == state.settings)) {
        std::string why;
        if (acceptEdit(edit, state.settings, why)) {
            state.refused.clear();
        } else {
            state.refused = why;
        }
    }
    if (!state.refused.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kRed);
        ImGui::TextWrapped("refused: %s", state.refused.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::PopItemWidth();
    ImGui::End();
    return actions;
}

} // namespace raylab::viewer
