#include "key_list.h"

#include <imgui.h>

namespace raylab::viewer {

namespace {

constexpr KeyHelp kKeys[] = {
    {"Up / Down", "move the camera forward / back"},
    {"Left / Right", "turn the camera (yaw)"},
    {"mouse drag, wheel", "turn the camera (fly), move it forward / back"},
    {"right drag, Alt + left drag", "orbit about the point under the cursor"},
    {"middle drag", "pan"},
    {"W / S, A / D, Q / E", "move the light forward / back, left / right, down / up"},
    {"V / Shift+V", "the next / previous view (beauty, albedo, direct, indirect, ...)"},
    {"Ctrl + click", "look inside that pixel: its equation with the numbers, its rays drawn"},
    {"O", "observer view on / off: a second camera sees the lab camera's frustum, the light and "
          "the inspected rays from outside; the keys, drags and undo then move the observer"},
    {"N", "the lab's N := the path-traced picture's mean N"},
    {"B", "A/B split on / off (drag its divider line)"},
    {"K", "keep the settings as snapshot A and compare live against it"},
    {"F (held)", "show the split's right side over the whole picture"},
    {"M", "the split's compare: wipe / signed difference left - right (live - A)"},
    {"Shift + drag", "a rectangle: the panel shows its mean R"},
    {"pointing at the picture", "the panel shows that pixel's R and its shown value"},
    {"Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y", "undo, redo (a drag or a walk is one step)"},
    {"Ctrl+1..9, 1..9", "keep the camera as a bookmark, return to it"},
    {"F12", "save a screenshot"},
    {"F1", "show / hide the panel (hidden, the picture takes the whole window)"},
    {"drag the panel's right edge", "a wider or narrower panel; the picture gets the rest"},
    {"H or ?", "show / hide this list"},
    {"Escape", "cancel a scene load; quit when none runs"},
};

} // namespace

std::span<const KeyHelp> keyList() { return kKeys; }

void drawKeyList(float x, float y) {
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Keys and mouse (H)", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoCollapse);
    if (ImGui::BeginTable("keys", 2)) {
        for (const KeyHelp& key : kKeys) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(key.input);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(key.does);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

} // namespace raylab::viewer
