#pragma once
// Puts a KeyEventGate (key_event_gate.h) between GLFW and Dear ImGui's GLFW backend, so that a
// key pressed and released within one frame (xdotool, fast typists) still reaches ImGui 1.86.
//
// The relay installs its own key and character callbacks in front of the ones the window has
// (those of ImGui's backend, installed with install_callbacks = true, which chain on to the
// viewer's InputCollector) and forwards every event to them, in arrival order, holding back the
// ones the gate keeps until a later frame. One relay per process (like GlWindow); construct it
// after PanelContext and destroy it before.

#include "key_event_gate.h"

struct GLFWwindow;

namespace raylab::viewer {

class KeyRelay {
public:
    explicit KeyRelay(GLFWwindow* window);
    KeyRelay(const KeyRelay&) = delete;
    KeyRelay& operator=(const KeyRelay&) = delete;
    // Puts back the callbacks it replaced; events still held back are dropped.
    ~KeyRelay();

    // Call after each ImGui frame ends (after ImGui::Render) and before events are polled again:
    // that frame's NewFrame has sampled the key state, so the events held back that fit the next
    // frame are forwarded now, outside any ImGui frame (ImGui asserts that modifiers do not change
    // within one).
    void frameEnded();
    // Whether events are held back for later frames (each later frame delivers some).
    bool holding() const { return gate_.waiting() > 0; }

private:
    using KeyFunction = void (*)(GLFWwindow*, int, int, int, int);
    using CharFunction = void (*)(GLFWwindow*, unsigned int);

    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onChar(GLFWwindow* window, unsigned int codepoint);
    void deliver(const KeyboardEvent& event) const;

    GLFWwindow* window_;
    KeyEventGate gate_;
    KeyFunction nextKey_ = nullptr; // the callbacks replaced, called for every event
    CharFunction nextChar_ = nullptr;
};

} // namespace raylab::viewer
