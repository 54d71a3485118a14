#pragma once
// How far an image is from a reference: the measure raylab-render --reference prints and the
// film's noise estimate (film.h) predicts.

#include "render/framebuffer.h"

namespace raylab {

// sqrt(mean over pixels and channels of (image - reference)^2) / (mean of the reference over
// pixels and channels). The images must have the same size; a reference whose mean is not > 0
// gives infinity. Non-finite pixels of the image count as infinitely wrong.
double relativeRmse(const Framebuffer& image, const Framebuffer& reference);

} // namespace raylab
