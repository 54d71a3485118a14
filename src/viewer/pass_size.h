#pragma once
// How many samples of each pixel the viewer's next pass takes (PassOptions::samples). More
// samples a pass trace faster (a tile's exact sums stay in cache) but show the picture less
// often, so a pass grows with the picture: one sample while it is young, later as many as fit a
// short time, never more than a quarter of what the picture holds (each new picture adds at most
// a quarter of its samples, so its noise falls in small steps) and never past the sample cap.

#include <cstddef>
#include <cstdint>

namespace raylab {

// The longest a pass of a converging picture may take, seconds: the picture still changes 10
// times a second. (A pass never holds the window up: a change cancels it between tiles.)
inline constexpr double kConvergingPassSeconds = 0.1;

// held: the samples the film holds; cap: the most it may hold (> held); secondsPerSample: the
// last pass's seconds per pixel and sample (0 when none was measured); pixels: the picture's.
// Returns a count in [1, min(cap - held, kSamplesPerPass)].
uint32_t passSamples(uint32_t held, uint32_t cap, double secondsPerSample, std::size_t pixels);

} // namespace raylab
