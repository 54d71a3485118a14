#include "pass_size.h"

#include "core/render/renderer.h"

#include <algorithm>

namespace raylab {

uint32_t passSamples(uint32_t held, uint32_t cap, double secondsPerSample, std::size_t pixels) {
    if (cap <= held + 1 || secondsPerSample <= 0.0 || pixels == 0) {
        return 1;
    }
    uint32_t samples = std::min({held / 4, cap - held, static_cast<uint32_t>(kSamplesPerPass)});
    const double passOfOne = secondsPerSample * static_cast<double>(pixels);
    while (samples > 1 && static_cast<double>(samples) * passOfOne > kConvergingPassSeconds) {
        samples /= 2;
    }
    return std::max(samples, 1u);
}

} // namespace raylab
