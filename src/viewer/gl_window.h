#pragma once
// The GLFW window with an OpenGL 3.3 core context, its GL functions loaded by glad.
// One per process: it initialises GLFW on creation and terminates it on destruction.

#include <string>

struct GLFWwindow;

namespace raylab::viewer {

class GlWindow {
public:
    GlWindow() = default;
    GlWindow(const GlWindow&) = delete;
    GlWindow& operator=(const GlWindow&) = delete;
    ~GlWindow();

    // Opens a width x height window (screen coordinates) titled `title`, hidden until show(),
    // makes its context current and loads GL. Returns false with a one-line error (no display,
    // no GL 3.3, ...).
    bool open(int width, int height, const std::string& title, std::string& error);
    void show();

    GLFWwindow* handle() const { return window_; }
    // The drawable size in pixels (differs from the window size on high-DPI screens); 0 x 0
    // while minimised.
    void framebufferSize(int& width, int& height) const;
    // Framebuffer pixels per screen coordinate (2 on a macOS Retina screen, else 1); 1 while
    // minimised.
    float framebufferScale() const;
    // True while the window is iconified (on X11 its framebuffer keeps its size) or its
    // framebuffer is empty (0 x 0, as minimised windows have elsewhere): nothing to draw.
    bool minimised() const;

private:
    GLFWwindow* window_ = nullptr;
    bool glfwStarted_ = false;
};

} // namespace raylab::viewer
