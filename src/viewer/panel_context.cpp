#include "panel_context.h"

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
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

ImDrawData& PanelContext::endFrame() {
    ImGui::Render();
    return *ImGui::GetDrawData();
}

} // namespace raylab::viewer
