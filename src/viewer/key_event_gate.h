#pragma once
// The order in which keyboard events may reach Dear ImGui 1.86 without being lost.
//
// ImGui 1.86 sees keys as a state (io.KeysDown) sampled once per frame by NewFrame, and handles a
// frame's characters before its key presses. So within one frame (from one NewFrame to the next):
//  - a key may change state (press or release) at most once: a press and its release in the same
//    frame would leave the key up at NewFrame and the press unseen;
//  - no character may follow a key press: ImGui would apply it before the press (Ctrl+A, then
//    typed text, would select the typed text instead of replacing the old one);
//  - no modifier (Shift, Ctrl, Alt, Super) may change after a key press: ImGui would see the
//    press with the modifiers of the end of the frame (xdotool's Ctrl+A releases Ctrl before A).
// An event that breaks either rule waits for a later frame, and every event after it waits too,
// so the order of events never changes. Key repeats change no state and pass when nothing waits.
// No GLFW or ImGui calls: the window glue is key_relay.h.

#include <cstddef>
#include <deque>
#include <utility>
#include <vector>

namespace raylab::viewer {

struct KeyboardEvent {
    enum class Kind { Key, Char };
    Kind kind = Kind::Key;
    // Key: GLFW's key, scancode, action (GLFW_PRESS, GLFW_RELEASE, GLFW_REPEAT) and mods.
    int key = 0;
    int scancode = 0;
    int action = 0;
    int mods = 0;
    unsigned codepoint = 0; // Char: the Unicode code point
};

class KeyEventGate {
public:
    // pressAction, releaseAction: the values of GLFW_PRESS and GLFW_RELEASE (any other action is
    // a repeat); modifierKeys: the key codes of the modifier keys.
    KeyEventGate(int pressAction, int releaseAction, std::vector<int> modifierKeys)
        : press_(pressAction), release_(releaseAction), modifiers_(std::move(modifierKeys)) {}

    // An event that just arrived. Returns true when it must be delivered now (it counts for the
    // current frame); false when the gate keeps it for a later frame.
    bool offer(const KeyboardEvent& event);
    // Starts a frame: call once ImGui's NewFrame has sampled the key state (after the ImGui
    // frame, before polling events). Returns, in order, the kept events to deliver now (they
    // count for the new frame); the rest stay kept.
    std::vector<KeyboardEvent> startFrame();
    std::size_t waiting() const { return waiting_.size(); }

private:
    bool fitsThisFrame(const KeyboardEvent& event) const;
    void count(const KeyboardEvent& event);

    int press_;
    int release_;
    std::vector<int> modifiers_;
    std::deque<KeyboardEvent> waiting_;
    std::vector<int> changedKeys_; // keys pressed or released in this frame
    bool pressedThisFrame_ = false;
};

} // namespace raylab::viewer
