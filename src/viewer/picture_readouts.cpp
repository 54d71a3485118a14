#include "picture_readouts.h"

namespace raylab::viewer {

void PictureReadouts::update(GLFWwindow* window, const InputEvents& events, bool panelHasMouse,
                             const PixelBox& area, const ShownImage& shown) {
    const int width = shown.bgra.width;
    const int height = shown.bgra.height;
    drag_.update(window, events.rectanglePressed && !panelHasMouse, area, width, height,
                 rectangle_);
    if (!panelHasMouse) {
        double x = 0.0, y = 0.0;
        cursorInPixels(window, x, y);
        int px = 0, py = 0;
        if (pixelUnderCursor(x, y, area, width, height, px, py)) {
            if (auto read = readPixel(shown, px, py)) {
                hover_ = read;
            }
        }
    }
    if (rectangle_ && !shown.preview && !shown.linear.pixels.empty()) {
        mean_ = viewer::rectangleMean(shown.linear, *rectangle_);
    }
}

} // namespace raylab::viewer
