#include "view_layout.h"

#include <algorithm>
#include <cmath>

namespace raylab::viewer {

int scaledPixels(float units, float uiScale, float framebufferScale) {
    return static_cast<int>(std::lround(static_cast<double>(units) * uiScale * framebufferScale));
}

bool PixelBox::contains(double px, double py) const {
    return px >= x && py >= y && px < static_cast<double>(x) + width &&
           py < static_cast<double>(y) + height;
}

ViewLayout viewLayout(int framebufferWidth, int framebufferHeight, bool panelShown, int panelWidth,
                      int minPanelWidth) {
    ViewLayout layout;
    layout.framebufferWidth = std::max(framebufferWidth, 0);
    layout.framebufferHeight = std::max(framebufferHeight, 0);
    if (layout.framebufferWidth == 0 || layout.framebufferHeight == 0) {
        return layout;
    }
    // The picture keeps at least one column.
    int column = panelShown ? std::min(panelWidth, layout.framebufferWidth - 1) : 0;
    if (column < std::max(minPanelWidth, 1)) {
        column = 0;
    }
    layout.panel = PixelBox{0, 0, column, column > 0 ? layout.framebufferHeight : 0};
    layout.picture =
        PixelBox{column, 0, layout.framebufferWidth - column, layout.framebufferHeight};
    return layout;
}

bool pixelUnderCursor(double x, double y, const PixelBox& picture, int renderWidth,
                      int renderHeight, int& px, int& py) {
    if (picture.empty() || renderWidth <= 0 || renderHeight <= 0 || !picture.contains(x, y)) {
        return false;
    }
    // The picture's pixel that the framebuffer pixel under the cursor shows: the one under that
    // pixel's centre, as shaders/quad.frag maps them, in integers.
    const auto shown = [](double offset, int pictureSide, int renderSide) {
        const long long pixel = static_cast<long long>(std::floor(offset));
        return static_cast<int>(std::min<long long>(renderSide - 1, (2 * pixel + 1) * renderSide /
                                                                        (2LL * pictureSide)));
    };
    px = shown(x - picture.x, picture.width, renderWidth);
    py = shown(y - picture.y, picture.height, renderHeight);
    return true;
}

PixelBox pictureToFramebuffer(const PixelBox& picture, int renderWidth, int renderHeight, int px0,
                              int py0, int px1, int py1) {
    if (picture.empty() || renderWidth <= 0 || renderHeight <= 0) {
        return {};
    }
    // The first framebuffer column (row) that shows picture column (row) i or a later one: the
    // first whose centre lies at or right of i's left edge, ceil(i * pictureSide / renderSide
    // - 0.5), in integers.
    const auto edge = [](int i, int pictureSide, int renderSide) {
        return static_cast<int>((2LL * i * pictureSide + renderSide - 1) / (2LL * renderSide));
    };
    const int left = edge(std::min(px0, px1), picture.width, renderWidth);
    const int right = edge(std::max(px0, px1) + 1, picture.width, renderWidth);
    const int top = edge(std::min(py0, py1), picture.height, renderHeight);
    const int bottom = edge(std::max(py0, py1) + 1, picture.height, renderHeight);
    return PixelBox{picture.x + left, picture.y + top, std::max(right - left, 1),
                    std::max(bottom - top, 1)};
}

GlBox glBox(const PixelBox& box, int framebufferHeight) {
    return GlBox{box.x, framebufferHeight - box.y - box.height, box.width, box.height};
}

PixelBox intersect(const PixelBox& box, const PixelBox& within) {
    const int x0 = std::max(box.x, within.x);
    const int y0 = std::max(box.y, within.y);
    const int x1 = std::min(box.x + box.width, within.x + within.width);
    const int y1 = std::min(box.y + box.height, within.y + within.height);
    if (x1 <= x0 || y1 <= y0) {
        return {};
    }
    return PixelBox{x0, y0, x1 - x0, y1 - y0};
}

float uiScaleFor(float contentScale, float framebufferScale) {
    if (!std::isfinite(contentScale) || !std::isfinite(framebufferScale) || contentScale <= 0.0f ||
        framebufferScale <= 0.0f) {
        return 1.0f;
    }
    return std::clamp(contentScale / framebufferScale, kMinUiScale, kMaxUiScale);
}

} // namespace raylab::viewer
