#include "parked_film.h"

#include <algorithm>
#include <utility>

namespace raylab::viewer {

bool ParkedFilm::exchange(const RenderJob& current, bool currentValid, const RenderJob& next,
                          Film& film) {
    const bool park = currentValid && !current.compare && film.samples() > 0;
    const bool resume =
        job_.scene && !next.compare && samePicture(next, job_) &&
        film_.samples() <= static_cast<uint32_t>(std::max(next.settings.samplesPerPixel, 0));
    if (!park && !resume) {
        return false;
    }
    std::swap(film, film_);
    job_ = park ? current : RenderJob{};
    return resume;
}

} // namespace raylab::viewer
