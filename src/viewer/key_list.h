#pragma once
// Every key and mouse gesture of the viewer with what it does: the list H (or ?) shows in the
// window. The README's table says the same for readers.

#include <span>

namespace raylab::viewer {

struct KeyHelp {
    const char* input;
    const char* does;
};

std::span<const KeyHelp> keyList();

// Draws the list as a Dear ImGui window centred on (x, y), in Dear ImGui's coordinates (for this
// ImGui frame).
void drawKeyList(float x, float y);

} // namespace raylab::viewer
