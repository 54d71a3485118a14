#pragma once
// The panel's Dear ImGui context on the window: the context, GLFW platform backend and OpenGL3
// renderer backend, set up in the order of Dear ImGui's example_glfw_opengl3 and torn down in
// reverse.

struct GLFWwindow;
struct ImDrawData;

namespace raylab::viewer {

class PanelContext {
public:
    // Installs ImGui's GLFW callbacks, which chain to the callbacks the window already has: set
    // the viewer's own callbacks before this. No imgui.ini is read or written.
    explicit PanelContext(GLFWwindow* window);
    PanelContext(const PanelContext&) = delete;
    PanelContext& operator=(const PanelContext&) = delete;
    ~PanelContext();

    bool ok() const { return ok_; }
    void beginFrame();
    // Builds the draw data of the frame; draw it with PanelCache::draw (or ImGui's renderer).
    // Valid until the next beginFrame.
    ImDrawData& endFrame();

private:
    bool platformReady_ = false;
    bool rendererReady_ = false;
    bool ok_ = false;
};

} // namespace raylab::viewer
