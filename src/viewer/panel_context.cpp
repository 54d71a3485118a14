#include "panel_context.h"

#include <cmath>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

namespace raylab::viewer {

PanelContext::PanelContext(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // the panel's place is fixed; nothing is written to the folder
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    platformReady_ = ImGui_ImplGlfw_InitForOpenGL(window, true);
    rendererReady_ = platformReady_ && ImGui_ImplOpenGL3_Init("#version 330 core");
    ok_ = platformReady_ && rendererReady_;
}

PanelContext::~PanelContext() {
    if (rendererReady_) {
        ImGui_ImplOpenGL3_Shutdown();
    }
    if (platformReady_) {
        ImGui_ImplGlfw_Shutdown();
    }
    ImGui::DestroyContext();
}

void PanelContext::beginFrame() {
    if (wantedScale_ != scale_) {
        scale_ = wantedScale_;
        ImGuiStyle style;
        ImGui::StyleColorsDark(&style);
        style.ScaleAllSizes(scale_);
        ImGui::GetStyle() = style;
        ImGuiIO& io = ImGui::GetIO();
        io.Fonts->Clear();
        ImFontConfig font;
        font.SizePixels = std::round(13.0f * scale_); // ProggyClean's own size, scaled
        io.Fonts->AddFontDefault(&font);
        if (framesBegun_) { // else the renderer builds the texture at its first frame
            ImGui_ImplOpenGL3_DestroyFontsTexture();
            ImGui_ImplOpenGL3_CreateFontsTexture();
        }
    }
    framesBegun_ = true;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

ImDrawData& PanelContext::endFrame() {
    ImGui::Render();
    return *ImGui::GetDrawData();
}

} // namespace raylab::viewer
