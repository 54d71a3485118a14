#pragma once
// For tests that build the panel's draw data with Dear ImGui but no window or GL.

#include <cstdint>
#include <imgui.h>

namespace raylab::viewer {

// A Dear ImGui context with its font atlas built, as a renderer backend would (no GL needed to
// build draw data).
class HeadlessImGui {
public:
    HeadlessImGui() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.LogFilename = nullptr;
        io.DisplaySize = ImVec2(1280.0f, 720.0f);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
        io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(1)));
        ImGui::StyleColorsDark();
    }
    HeadlessImGui(const HeadlessImGui&) = delete;
    HeadlessImGui& operator=(const HeadlessImGui&) = delete;
    ~HeadlessImGui() { ImGui::DestroyContext(); }
};

} // namespace raylab::viewer
