#pragma once
// The A/B split: one picture made of two, the left `divider` of its width from one and the rest
// from the other (viewer/render_worker.h renders both). The column where a side begins is
// splitColumn(width, divider), the same for display bytes and linear pictures.

#include "core/render/framebuffer.h"
#include "core/render_settings.h"

#include <cstdint>
#include <span>

namespace raylab::viewer {

// The right side of the viewer's integrator split: the same settings with the other integrator.
RenderSettings otherIntegrator(const RenderSettings& settings);

// The right side of a split of `live`: `snapshot` (at live's size, threads and sample cap) when
// given, else the other integrator.
RenderSettings splitCompare(const RenderSettings& live, const RenderSettings* snapshot);

// Whether a press at cursor column x (framebuffer pixels) grabs the divider of a picture
// `width` pixels wide: within kDividerGrabPixels of its column.
inline constexpr double kDividerGrabPixels = 8.0;
bool grabsDivider(double x, int width, float divider);

// The first column shown from the right side: round(divider * width), clamped to [0, width].
int splitColumn(int width, float divider);

// out = left's columns [0, splitColumn) and right's columns from it on, 4 bytes a pixel; out may
// be left or right itself. All three hold 4 * width * height bytes.
void composeSplit(std::span<const uint8_t> left, std::span<const uint8_t> right, int width,
                  int height, float divider, std::span<uint8_t> out);

// The same for linear pictures of one size: left's pixels right of the divider become right's.
void composeSplit(Framebuffer& left, const Framebuffer& right, float divider);

} // namespace raylab::viewer
