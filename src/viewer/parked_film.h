#pragma once
// The render thread's memory of the last picture it replaced: when a new job replaces a picture
// of one side (no split) that has samples, its job and film are parked here, and a later job of
// that same picture (samePicture: the observer view switched back to the lab camera, an undo)
// takes the film back and resumes accumulating instead of starting again. One picture is kept;
// it holds its scene alive until another takes its place.

#include "core/render/film.h"
#include "render_worker.h"

namespace raylab::viewer {

class ParkedFilm {
public:
    // `current` (whose accumulation `film` holds when `currentValid`) is replaced by `next`.
    // When `next` is the parked picture and its samples do not exceed next's cap, `film` takes
    // the parked samples and true is returned; otherwise false and `film` is for the caller to
    // restart. Either way `current`'s samples, when it had any and is not split, are parked.
    bool exchange(const RenderJob& current, bool currentValid, const RenderJob& next, Film& film);

private:
    RenderJob job_; // no scene: nothing parked
    Film film_;
};

} // namespace raylab::viewer
