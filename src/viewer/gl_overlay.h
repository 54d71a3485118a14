#pragma once
// What the viewer draws over the traced picture with GL (never into the picture or its
// screenshots): the split's divider and the inspected pixel's marker. Both clear small
// scissored rectangles of the default framebuffer; call them after the picture's quad.

namespace raylab::viewer {

void drawDivider(int x, int framebufferHeight);
void drawPixelMarker(int px, int py, int width, int height, int framebufferWidth,
                     int framebufferHeight);

} // namespace raylab::viewer
