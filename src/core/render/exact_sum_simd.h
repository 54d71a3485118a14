#pragma once
// Adding the samples of eight neighbouring pixels to their exact sums at once (exact_sum.h):
// with AVX-512 the 24 floats become 128-bit fixed-point values from their bits (no float
// arithmetic: the significand shifted into place) and are added with their carries in six
// vector adds. The sums are bit for bit those of PixelSum::add pixel by pixel; floats outside
// toFixed's exact range (or a CPU without AVX-512) take the scalar path.

#include "render/film.h"

namespace raylab {

// sums[k].add({r[k], g[k], b[k]}) for k < 8, by the fastest path this CPU has.
void addSamples8(PixelSum* sums, const float* r, const float* g, const float* b);

// The two paths, for tests. addSamples8Avx512 returns false, and adds nothing, when a value is
// outside [2^-40, 2^31) in magnitude and not 0 (NaN, infinities, huge or tiny values), or when
// the CPU lacks AVX-512 (F and DQ).
void addSamples8Scalar(PixelSum* sums, const float* r, const float* g, const float* b);
bool addSamples8Avx512(PixelSum* sums, const float* r, const float* g, const float* b);
bool avx512Supported();

} // namespace raylab
