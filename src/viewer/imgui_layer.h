#pragma once
// Dear ImGui on the window: context, GLFW platform backend and OpenGL3 renderer backend, set up in
// the order of Dear ImGui's example_glfw_opengl3 and torn down in reverse.

struct GLFWwindow;

namespace raylab::viewer {

class ImGuiLayer {
public:
    // Installs ImGui's GLFW callbacks, which chain to the callbacks the window already has: set
    // the viewer's own callbacks before this. No imgui.ini is read or written.
    explicit ImGuiLayer(GLFWwindow* window);
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;
    ~ImGuiLayer();

    bool ok() const { return ok_; }
    void beginFrame();
    // Builds the draw data of the frame and draws it over what the framebuffer holds.
    void endFrame();

private:
    bool platformReady_ = false;
    bool rendererReady_ = false;
    bool ok_ = false;
};

} // namespace raylab::viewer
