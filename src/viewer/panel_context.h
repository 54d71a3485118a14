#pragma once
// The panel's Dear ImGui context on the window: the context, GLFW platform backend and OpenGL3
// renderer backend, set up in the order of Dear ImGui's example_glfw_opengl3 and torn down in
// reverse. Its UI scale (a monitor's content scale, or --ui-scale) scales the style's sizes and
// the font, which is rasterised again at the scaled size (not stretched).

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
    // Dear ImGui's dark style with every size times `scale`, and its default font at 13 * scale
    // pixels, from the next beginFrame on. 1 at first.
    void setScale(float scale) { wantedScale_ = scale; }
    float scale() const { return wantedScale_; }
    void beginFrame();
    // Builds the draw data of the frame; draw it with PanelLayer::composite (or ImGui's renderer).
    // Valid until the next beginFrame.
    ImDrawData& endFrame();

private:
    bool platformReady_ = false;
    bool rendererReady_ = false;
    bool ok_ = false;
    bool framesBegun_ = false; // the renderer has made its font texture (at its first frame)
    float wantedScale_ = 1.0f;
    float scale_ = 0.0f; // the scale applied; 0: none yet
};

} // namespace raylab::viewer
