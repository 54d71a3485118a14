#include "sampling/sampler.h"

#include <cstring>

namespace raylab {

const char* toString(SamplerKind kind) {
    return kind == SamplerKind::Independent ? "independent" : "sobol";
}

bool parseSamplerKind(const char* text, SamplerKind& kind) {
    if (std::strcmp(text, "sobol") == 0) {
        kind = SamplerKind::Sobol;
        return true;
    }
    if (std::strcmp(text, "independent") == 0) {
        kind = SamplerKind::Independent;
        return true;
    }
    return false;
}

} // namespace raylab
