#include "key_relay.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

namespace {

// The relay of the process's window; GLFW's callbacks carry no context of their own (the window's
// user pointer belongs to InputCollector).
KeyRelay* activeRelay = nullptr;

} // namespace

KeyRelay::KeyRelay(GLFWwindow* window)
    : window_(window), gate_(GLFW_PRESS, GLFW_RELEASE,
                             {GLFW_KEY_LEFT_SHIFT, GLFW_KEY_LEFT_CONTROL, GLFW_KEY_LEFT_ALT,
                              GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SHIFT, GLFW_KEY_RIGHT_CONTROL,
                              GLFW_KEY_RIGHT_ALT, GLFW_KEY_RIGHT_SUPER}) {
    activeRelay = this;
    nextKey_ = glfwSetKeyCallback(window_, &KeyRelay::onKey);
    nextChar_ = glfwSetCharCallback(window_, &KeyRelay::onChar);
}

KeyRelay::~KeyRelay() {
    glfwSetKeyCallback(window_, nextKey_);
    glfwSetCharCallback(window_, nextChar_);
    activeRelay = nullptr;
}

void KeyRelay::frameEnded() {
    for (const KeyboardEvent& event : gate_.startFrame()) {
        deliver(event);
    }
}

void KeyRelay::deliver(const KeyboardEvent& event) const {
    if (event.kind == KeyboardEvent::Kind::Char) {
        if (nextChar_ != nullptr) {
            nextChar_(window_, event.codepoint);
        }
    } else if (nextKey_ != nullptr) {
        nextKey_(window_, event.key, event.scancode, event.action, event.mods);
    }
}

void KeyRelay::onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
    if (activeRelay == nullptr || window != activeRelay->window_) {
        return;
    }
    KeyboardEvent event;
    event.key = key;
    event.scancode = scancode;
    event.action = action;
    event.mods = mods;
    if (activeRelay->gate_.offer(event)) {
        activeRelay->deliver(event);
    }
}

void KeyRelay::onChar(GLFWwindow* window, unsigned int codepoint) {
    if (activeRelay == nullptr || window != activeRelay->window_) {
        return;
    }
    KeyboardEvent event;
    event.kind = KeyboardEvent::Kind::Char;
    event.codepoint = codepoint;
    if (activeRelay->gate_.offer(event)) {
        activeRelay->deliver(event);
    }
}

} // namespace raylab::viewer
