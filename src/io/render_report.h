#pragma once
// Pieces of the one-line summaries raylab-render and raylab-merge print on stderr.

#include "core/render/film.h"

#include <string>

namespace raylab {

// ", noise 1.234%" when the film's noise estimate is known, else empty.
inline std::string noiseSuffix(const NoiseEstimate& noise) {
    if (!noise.known) {
        return {};
    }
    return ", noise " + std::to_string(100.0 * noise.relativeError).substr(0, 5) + "%";
}

} // namespace raylab
