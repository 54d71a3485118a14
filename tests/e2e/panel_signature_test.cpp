// panelSignature on the real panel's draw data, built by Dear ImGui without a window or GL: the
// same panel gives the same signature; a hover, an edited value, a new number or another display
// size change it; the bounds hold the panel and nothing far from it.

#include "headless_imgui.h"
#include "panel.h"
#include "panel_signature.h"

#include <cfloat>
#include <gtest/gtest.h>
#include <imgui.h>

namespace raylab::viewer {
namespace {

// Draws one frame of the panel and returns its signature.
PanelSignature panelFrame(PanelState& state, const PanelView& view) {
    ImGui::NewFrame();
    drawPanel(state, view);
    ImGui::Render();
    return panelSignature(*ImGui::GetDrawData());
}

// A few frames, as the viewer draws after an event (ImGui settles: hover, auto-resize).
PanelSignature settled(PanelState& state, const PanelView& view) {
    PanelSignature last;
    for (int i = 0; i < 4; ++i) {
        last = panelFrame(state, view);
    }
    return last;
}

TEST(ViewerPanelSignature, SamePanelSameSignatureAndChangesShow) {
    HeadlessImGui imgui;
    PanelState state;
    state.scenePath = "cornell";
    PanelNumbers numbers;
    numbers.picture = {1280, 720, 16, false, false, 40.0, 2.5e7};
    PanelView view;
    view.sceneName = "cornell";
    view.triangles = 30;
    view.numbers = &numbers;
    ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX); // no mouse over the window

    const PanelSignature first = settled(state, view);
    EXPECT_EQ(panelFrame(state, view), first) << "an unchanged panel changed its draw data";
    EXPECT_EQ(panelFrame(state, view), first);

    // Bounds: the panel's column (the left edge, its width, the display's height), no more.
    EXPECT_EQ(first.bounds, (PixelRect{0, 0, static_cast<int>(kPanelColumnWidth), 720}));

    // The mouse over the screenshot button highlights it (the viewer re-renders in that frame).
    ImGui::GetIO().MousePos = ImVec2(100.0f, 17.0f);
    const PanelSignature hovered = panelFrame(state, view);
    EXPECT_NE(hovered.hash, first.hash);
    EXPECT_EQ(settled(state, view), hovered);
    ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    EXPECT_EQ(settled(state, view), first);

    // An edited value (as a key or the mouse would change it) and a new number show.
    state.settings.light.intensity += 1.0f;
    const PanelSignature edited = panelFrame(state, view);
    EXPECT_NE(edited.hash, first.hash);
    numbers.picture.samples = 17;
    EXPECT_NE(panelFrame(state, view).hash, edited.hash);
    numbers.drawMs.push(3.0f);
    const PanelSignature plotted = panelFrame(state, view);
    EXPECT_NE(plotted.hash, edited.hash);
    EXPECT_EQ(panelFrame(state, view), plotted);

    // Another display size: another signature, even where the panel looks the same.
    ImGui::GetIO().DisplaySize = ImVec2(1000.0f, 720.0f);
    EXPECT_NE(settled(state, view).hash, plotted.hash);
}

TEST(ViewerPanelSignature, ThePanelFillsTheColumnItIsGiven) {
    HeadlessImGui imgui;
    PanelState state;
    PanelView view;
    ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    view.width = 720.0f; // a column twice as wide, as at UI scale 2
    view.maxWidth = 1000.0f;
    EXPECT_EQ(settled(state, view).bounds, (PixelRect{0, 0, 720, 720}));
    // Dragged by nobody, the panel reports no resize.
    ImGui::NewFrame();
    EXPECT_EQ(drawPanel(state, view).resizedTo, 0.0f);
    ImGui::Render();
}

TEST(ViewerPanelSignature, NothingDrawnHasEmptyBounds) {
    HeadlessImGui imgui;
    ImGui::NewFrame();
    ImGui::Render();
    const PanelSignature none = panelSignature(*ImGui::GetDrawData());
    EXPECT_TRUE(none.bounds.empty());
    ImGui::NewFrame();
    ImGui::Render();
    EXPECT_EQ(panelSignature(*ImGui::GetDrawData()), none);
}

TEST(ViewerPanelSignature, UniteIgnoresEmptyRectangles) {
    const PixelRect a{1, 2, 5, 6}, b{3, 0, 9, 4}, empty{};
    EXPECT_EQ(unite(a, b), (PixelRect{1, 0, 9, 6}));
    EXPECT_EQ(unite(a, empty), a);
    EXPECT_EQ(unite(empty, b), b);
    EXPECT_TRUE(unite(empty, empty).empty());
}

} // namespace
} // namespace raylab::viewer
