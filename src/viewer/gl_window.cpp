#include "gl_window.h"

#include <glad/gl.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace raylab::viewer {

GlWindow::~GlWindow() {
    if (window_ != nullptr) {
        glfwDestroyWindow(window_);
    }
    if (glfwStarted_) {
        glfwTerminate();
    }
}

bool GlWindow::open(int width, int height, const std::string& title, std::string& error) {
    if (glfwInit() != GLFW_TRUE) {
        const char* why = nullptr;
        glfwGetError(&why);
        error = std::string("cannot start GLFW: ") + (why ? why : "unknown error");
        return false;
    }
    glfwStarted_ = true;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE); // required on macOS, harmless elsewhere
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);      // honour the monitor's content scale
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE); // shown once sized for the panel (show())
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        const char* why = nullptr;
        glfwGetError(&why);
        error =
            std::string("cannot open an OpenGL 3.3 core window: ") + (why ? why : "unknown error");
        return false;
    }
    glfwMakeContextCurrent(window_);
    if (gladLoadGL(glfwGetProcAddress) == 0) {
        error = "cannot load the OpenGL 3.3 functions (glad)";
        return false;
    }
    glfwSwapInterval(1);
    return true;
}

void GlWindow::show() { glfwShowWindow(window_); }

void GlWindow::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
}

float GlWindow::framebufferScale() const {
    int width = 0, height = 0, pixels = 0;
    glfwGetWindowSize(window_, &width, &height);
    glfwGetFramebufferSize(window_, &pixels, &height);
    return width > 0 && pixels > 0 ? static_cast<float>(pixels) / static_cast<float>(width) : 1.0f;
}

bool GlWindow::minimised() const {
    int width = 0, height = 0;
    framebufferSize(width, height);
    return width <= 0 || height <= 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED) != 0;
}

} // namespace raylab::viewer
