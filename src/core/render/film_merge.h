#pragma once
// Adding up the parts of a render split over machines: each part holds a sample range of a window
// of the picture (a Film's sums). The parts must cover every pixel's samples 0..N-1 exactly once,
// for one N; then their exact sums add to the sums of the render made in one go, and the merged
// film's mean is that render's picture, bit for bit.

#include "render/film.h"

#include <span>
#include <string>

namespace raylab {

struct FilmPart {
    std::string name; // for messages (the file's name)
    FilmWindow window;
    uint32_t firstSample = 0; // samples [firstSample, endSample)
    uint32_t endSample = 0;
    std::span<const PixelSum> sums;     // window.width() x window.height(), row-major
    std::span<const glm::vec3> squares; // the same size, or empty
};

// Checks that the parts cover samples 0..N-1 of every pixel of a width x height picture exactly
// once (N the largest endSample), and adds them into `film` (reset to the whole picture, holding
// samples 0..N-1; its noise moments kept when every part has them). Returns an empty string, or
// one line naming the first pixels whose samples are missing or given twice (and by which
// parts), leaving `film` unspecified.
std::string mergeFilmParts(int width, int height, std::span<const FilmPart> parts, Film& film);

} // namespace raylab
