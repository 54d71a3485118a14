#pragma once
// Keyboard and mouse events of the window, collected by GLFW callbacks between two frames and
// handed to the frame in one piece. Key presses are queued as events (not polled), so a press and
// release within one frame (as xdotool sends them) is never lost. Every input or window event
// (also releases, characters, cursor moves, focus, resize, expose, minimise, a new content
// scale) is noted, so the
// window knows that a frame is wanted (redraw_schedule.h).
//
// The navigation keys (navActionForKey) are recorded apart, as presses and releases with the time
// they arrived, for held_keys.h: a held key moves smoothly, so their key repeats are dropped.
// Losing the focus is recorded among them (GLFW does not always send the releases then).

#include "navigation.h"
#include "view_layout.h"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace raylab::viewer {

enum class Command {
    Screenshot,
    Quit,
    TogglePanel,
    UseMeanIndirect,
    ToggleSplit,
    NextView,
    KeepSnapshot,
    ToggleKeyList,
    NextCompareMode, // M: the split's wipe <-> difference
    Undo,            // Z, with Ctrl
    Redo,            // Y, or Z with Shift, with Ctrl
    ToggleObserver,  // O: the observer view on / off (observer_view.h)
};

// A change of the held navigation keys: a navigation key went down or up, or the window lost
// the focus (every key counts as up then).
struct NavKeyChange {
    enum class Kind { Press, Release, FocusLost };
    Kind kind = Kind::Press;
    NavAction action = NavAction::CameraForward; // Press and Release only
    std::chrono::steady_clock::time_point when;  // when the callback saw it
};

struct InputEvents {
    // GLFW key codes of the presses and repeats of the keys that do not navigate, in order.
    std::vector<int> keys;
    std::vector<NavKeyChange> navKeys; // the navigation keys' changes, in order; no repeats
    std::vector<std::string> dropped;  // paths dropped on the window, in order
    double scroll = 0.0;               // wheel notches, positive = away from the user
    bool leftPressed = false;          // the left button went down
    bool inspectPressed = false;       // ... with Ctrl held: look inside the pixel under it
    bool rectanglePressed = false;     // ... with Shift held: drag a rectangle to read its mean
    bool orbitPressed = false;         // the right button (or Alt + left) went down: orbit
    bool panPressed = false;           // the middle button went down: pan
    bool keyboard = false;             // a key (press, repeat, release) or a character arrived
    bool other = false;                // a mouse, cursor or window event arrived
    bool contentScale = false;         // the window's content scale changed (another monitor)
};

class InputCollector {
public:
    // Installs the collector's key, scroll and mouse-button callbacks and makes it the window's
    // user pointer. Call before ImGui installs its callbacks (they chain to these). The collector
    // must outlive the window's event processing.
    void attach(GLFWwindow* window);
    // The events since the last call.
    InputEvents take();
    // The events since the last take(), left in place.
    const InputEvents& pending() const { return events_; }
    // The navigation keys' changes since the last take() or takeNavKeys(), taken out of them.
    std::vector<NavKeyChange> takeNavKeys();

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onScroll(GLFWwindow* window, double dx, double dy);
    static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
    static void onChar(GLFWwindow* window, unsigned int codepoint);
    static void onCursor(GLFWwindow* window, double x, double y);
    static void onEnter(GLFWwindow* window, int entered);
    static void onFocus(GLFWwindow* window, int focused);
    static void onSize(GLFWwindow* window, int width, int height);
    static void onRefresh(GLFWwindow* window);
    static void onIconify(GLFWwindow* window, int iconified);
    static void onDrop(GLFWwindow* window, int count, const char** paths);
    static void onContentScale(GLFWwindow* window, float xscale, float yscale);
    InputEvents events_;
};

// The lab's keys; empty for keys that do not navigate.
std::optional<NavAction> navActionForKey(int glfwKey);
// F12: screenshot, Escape: quit (the viewer makes it cancel a running scene load first), F1:
// show or hide the panel.
std::optional<Command> commandForKey(int glfwKey);

// The mouse drag that turns the camera: while the left button, pressed outside the panel, is
// held, the point under the cursor follows the cursor (a drag to the right turns the camera left).
// The camera bookmark slot of a key: 0..8 for the keys 1..9 (top row or keypad), else nullopt.
std::optional<int> bookmarkForKey(int glfwKey);

// The cursor in framebuffer pixels (screen coordinates scaled on high-DPI screens).
void cursorInPixels(GLFWwindow* window, double& x, double& y);

// The split's divider under the mouse: a press that grabs it (grabsDivider) moves it with the
// cursor until the button is released, instead of turning the camera.
class DividerDrag {
public:
    // `start`: a press outside the panel happened now; `picture`: the picture's box in the
    // framebuffer (view_layout.h). Updates `divider` while dragging and returns whether a
    // divider drag is under way (then the press is not the camera's).
    bool update(GLFWwindow* window, bool start, const PixelBox& picture, float& divider);

private:
    bool dragging_ = false;
};

// A drag with one button: the cursor's motion (framebuffer pixels) since the last update while
// the button stays down after a press that `start`ed it.
class ButtonDrag {
public:
    explicit ButtonDrag(int glfwButton) : button_(glfwButton) {}
    // Returns whether the drag is under way; dx, dy: the motion since the last update.
    bool update(GLFWwindow* window, bool start, double& dx, double& dy);

private:
    int button_;
    bool dragging_ = false;
    double lastX_ = 0.0, lastY_ = 0.0;
};

class MouseDrag {
public:
    // Returns the yaw and pitch (degrees) to apply this frame. `start` is whether a press
    // outside the panel happened this frame; `degreesPerPixel` = vertical fov / framebuffer height.
    void update(GLFWwindow* window, bool start, float degreesPerPixel, float& yaw, float& pitch);
    // Whether a drag is under way (as of the last update).
    bool dragging() const { return dragging_; }

private:
    bool dragging_ = false;
    double lastX_ = 0.0, lastY_ = 0.0; // framebuffer pixels
};

} // namespace raylab::viewer
