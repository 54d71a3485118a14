#include "input.h"

#include "split_view.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

namespace {

InputCollector* collectorOf(GLFWwindow* window) {
    return static_cast<InputCollector*>(glfwGetWindowUserPointer(window));
}

} // namespace

std::optional<int> bookmarkForKey(int glfwKey) {
    if (glfwKey >= GLFW_KEY_1 && glfwKey <= GLFW_KEY_9) {
        return glfwKey - GLFW_KEY_1;
    }
    if (glfwKey >= GLFW_KEY_KP_1 && glfwKey <= GLFW_KEY_KP_9) {
        return glfwKey - GLFW_KEY_KP_1;
    }
    return std::nullopt;
}

void cursorInPixels(GLFWwindow* window, double& x, double& y) {
    int windowWidth = 0, windowHeight = 0, pixelWidth = 0, pixelHeight = 0;
    glfwGetWindowSize(window, &windowWidth, &windowHeight);
    glfwGetFramebufferSize(window, &pixelWidth, &pixelHeight);
    glfwGetCursorPos(window, &x, &y);
    if (windowWidth > 0 && windowHeight > 0) {
        x *= static_cast<double>(pixelWidth) / windowWidth;
        y *= static_cast<double>(pixelHeight) / windowHeight;
    }
}

void InputCollector::attach(GLFWwindow* window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, &InputCollector::onKey);
    glfwSetScrollCallback(window, &InputCollector::onScroll);
    glfwSetMouseButtonCallback(window, &InputCollector::onMouseButton);
    glfwSetCharCallback(window, &InputCollector::onChar);
    glfwSetCursorPosCallback(window, &InputCollector::onCursor);
    glfwSetCursorEnterCallback(window, &InputCollector::onEnter);
    glfwSetWindowFocusCallback(window, &InputCollector::onFocus);
    glfwSetFramebufferSizeCallback(window, &InputCollector::onSize);
    glfwSetWindowRefreshCallback(window, &InputCollector::onRefresh);
    glfwSetWindowIconifyCallback(window, &InputCollector::onIconify);
    glfwSetDropCallback(window, &InputCollector::onDrop);
    glfwSetWindowContentScaleCallback(window, &InputCollector::onContentScale);
}

InputEvents InputCollector::take() {
    InputEvents out = std::move(events_);
    events_ = {};
    return out;
}

std::vector<NavKeyChange> InputCollector::takeNavKeys() {
    std::vector<NavKeyChange> out = std::move(events_.navKeys);
    events_.navKeys.clear();
    return out;
}

void InputCollector::onKey(GLFWwindow* window, int key, int, int action, int) {
    InputEvents& events = collectorOf(window)->events_;
    events.keyboard = true;
    if (const auto navAction = navActionForKey(key)) {
        // Held keys move by the time they are held; their repeats would move them twice.
        if (action == GLFW_PRESS || action == GLFW_RELEASE) {
            const auto kind =
                action == GLFW_PRESS ? NavKeyChange::Kind::Press : NavKeyChange::Kind::Release;
            events.navKeys.push_back({kind, *navAction, std::chrono::steady_clock::now()});
        }
    } else if (action == GLFW_PRESS || action == GLFW_REPEAT) {
        events.keys.push_back(key);
    }
}

void InputCollector::onScroll(GLFWwindow* window, double, double dy) {
    InputEvents& events = collectorOf(window)->events_;
    events.other = true;
    events.scroll += dy;
}

void InputCollector::onMouseButton(GLFWwindow* window, int button, int action, int mods) {
    InputEvents& events = collectorOf(window)->events_;
    events.other = true;
    if (action != GLFW_PRESS) {
        return;
    }
    if (button == GLFW_MOUSE_BUTTON_LEFT) {
        if ((mods & GLFW_MOD_CONTROL) != 0) {
            events.inspectPressed = true;
        } else if ((mods & GLFW_MOD_ALT) != 0) {
            events.orbitPressed = true;
        } else if ((mods & GLFW_MOD_SHIFT) != 0) {
            events.rectanglePressed = true;
        } else {
            events.leftPressed = true;
        }
    } else if (button == GLFW_MOUSE_BUTTON_RIGHT) {
        events.orbitPressed = true;
    } else if (button == GLFW_MOUSE_BUTTON_MIDDLE) {
        events.panPressed = true;
    }
}

void InputCollector::onDrop(GLFWwindow* window, int count, const char** paths) {
    InputEvents& events = collectorOf(window)->events_;
    events.other = true;
    for (int i = 0; i < count; ++i) {
        events.dropped.emplace_back(paths[i]);
    }
}

void InputCollector::onContentScale(GLFWwindow* window, float, float) {
    InputEvents& events = collectorOf(window)->events_;
    events.other = true;
    events.contentScale = true;
}

void InputCollector::onChar(GLFWwindow* window, unsigned int) {
    collectorOf(window)->events_.keyboard = true;
}

void InputCollector::onCursor(GLFWwindow* window, double, double) {
    collectorOf(window)->events_.other = true;
}

void InputCollector::onEnter(GLFWwindow* window, int) { collectorOf(window)->events_.other = true; }

void InputCollector::onFocus(GLFWwindow* window, int focused) {
    InputEvents& events = collectorOf(window)->events_;
    events.other = true;
    if (focused == GLFW_FALSE) {
        NavKeyChange lost;
        lost.kind = NavKeyChange::Kind::FocusLost;
        lost.when = std::chrono::steady_clock::now();
        events.navKeys.push_back(lost);
    }
}

void InputCollector::onSize(GLFWwindow* window, int, int) {
    collectorOf(window)->events_.other = true;
}

void InputCollector::onRefresh(GLFWwindow* window) { collectorOf(window)->events_.other = true; }

void InputCollector::onIconify(GLFWwindow* window, int) {
    collectorOf(window)->events_.other = true;
}

std::optional<NavAction> navActionForKey(int glfwKey) {
    switch (glfwKey) {
    case GLFW_KEY_UP: return NavAction::CameraForward;
    case GLFW_KEY_DOWN: return NavAction::CameraBack;
    case GLFW_KEY_LEFT: return NavAction::TurnLeft;
    case GLFW_KEY_RIGHT: return NavAction::TurnRight;
    case GLFW_KEY_W: return NavAction::LightForward;
    case GLFW_KEY_S: return NavAction::LightBack;
    case GLFW_KEY_A: return NavAction::LightLeft;
    case GLFW_KEY_D: return NavAction::LightRight;
    case GLFW_KEY_Q: return NavAction::LightDown;
    case GLFW_KEY_E: return NavAction::LightUp;
    default: return std::nullopt;
    }
}

std::optional<Command> commandForKey(int glfwKey) {
    switch (glfwKey) {
    case GLFW_KEY_F12: return Command::Screenshot;
    case GLFW_KEY_ESCAPE: return Command::Quit;
    case GLFW_KEY_F1: return Command::TogglePanel;
    case GLFW_KEY_N: return Command::UseMeanIndirect;
    case GLFW_KEY_B: return Command::ToggleSplit;
    case GLFW_KEY_V: return Command::NextView;
    case GLFW_KEY_K: return Command::KeepSnapshot;
    case GLFW_KEY_M: return Command::NextCompareMode;
    case GLFW_KEY_H:
    case GLFW_KEY_SLASH: return Command::ToggleKeyList; // H, or ? (Shift + /)
    case GLFW_KEY_Z: return Command::Undo;
    case GLFW_KEY_Y: return Command::Redo;
    case GLFW_KEY_O: return Command::ToggleObserver;
    default: return std::nullopt;
    }
}

bool DividerDrag::update(GLFWwindow* window, bool start, const PixelBox& picture, float& divider) {
    if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS && !start) {
        dragging_ = false;
        return false;
    }
    double x = 0.0, y = 0.0;
    cursorInPixels(window, x, y);
    x -= picture.x; // the divider's column counts from the picture's left edge
    if (start) {
        dragging_ = picture.contains(x + picture.x, y) && grabsDivider(x, picture.width, divider);
    }
    if (dragging_ && picture.width > 0) {
        divider = std::clamp(static_cast<float>(x / picture.width), 0.0f, 1.0f);
    }
    return dragging_;
}

bool ButtonDrag::update(GLFWwindow* window, bool start, double& dx, double& dy) {
    dx = 0.0;
    dy = 0.0;
    // An Alt + left orbit holds the left button.
    const bool down = glfwGetMouseButton(window, button_) == GLFW_PRESS ||
                      (button_ == GLFW_MOUSE_BUTTON_RIGHT &&
                       glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS);
    if (!down && !start) {
        dragging_ = false;
        return false;
    }
    double x = 0.0, y = 0.0;
    cursorInPixels(window, x, y);
    if (start) {
        dragging_ = true;
    } else if (dragging_) {
        dx = x - lastX_;
        dy = y - lastY_;
    }
    lastX_ = x;
    lastY_ = y;
    return dragging_;
}

void MouseDrag::update(GLFWwindow* window, bool start, float degreesPerPixel, float& yaw,
                       float& pitch) {
    yaw = 0.0f;
    pitch = 0.0f;
    if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) != GLFW_PRESS && !start) {
        dragging_ = false;
        return;
    }
    double x = 0.0, y = 0.0;
    cursorInPixels(window, x, y);
    if (start) {
        dragging_ = true;
    } else if (dragging_) {
        // Grab the view: moving the cursor right turns the camera left (yaw up); down looks up.
        yaw = static_cast<float>(x - lastX_) * degreesPerPixel;
        pitch = static_cast<float>(y - lastY_) * degreesPerPixel;
    }
    lastX_ = x;
    lastY_ = y;
}

} // namespace raylab::viewer
