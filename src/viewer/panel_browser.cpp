#include "panel_browser.h"

#include <cstdio>
#include <imgui.h>

namespace raylab {

namespace {

// "12.3 MB": a file's size in the list.
std::string sizeText(std::uintmax_t bytes) {
    char text[32];
    if (bytes >= 1000000) {
        std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) * 1e-6);
    } else {
        std::snprintf(text, sizeof text, "%.1f kB", static_cast<double>(bytes) * 1e-3);
    }
    return text;
}

} // namespace

bool drawFileBrowser(FileBrowser& browser, std::string& chosen) {
    ImGui::TextWrapped("%s", browser.folder().string().c_str());
    if (!browser.error().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", browser.error().c_str());
        ImGui::PopStyleColor();
    }
    bool picked = false;
    const float rows = 12.0f;
    ImGui::BeginChild("##browser", ImVec2(-1.0f, rows * ImGui::GetTextLineHeightWithSpacing()),
                      true);
    const auto& entries = browser.entries();
    std::size_t clicked = entries.size();
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const BrowserEntry& e = entries[i];
        const std::string label = e.folder ? e.name + "/" : e.name;
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_AllowDoubleClick)) {
            clicked = i;
        }
        if (!e.folder) {
            const std::string size = sizeText(e.bytes);
            ImGui::SameLine(ImGui::GetWindowContentRegionMax().x -
                            ImGui::CalcTextSize(size.c_str()).x);
            ImGui::TextDisabled("%s", size.c_str());
        }
        ImGui::PopID();
    }
    if (entries.empty()) {
        ImGui::TextDisabled("no folders or mesh files here");
    }
    if (browser.leftOut() > 0) {
        ImGui::TextDisabled("and %zu more not listed", browser.leftOut());
    }
    ImGui::EndChild();
    // Acted on after the list is drawn: choosing a folder replaces the entries.
    if (clicked < entries.size()) {
        picked = browser.choose(clicked, chosen);
    }
    return picked;
}

} // namespace raylab
