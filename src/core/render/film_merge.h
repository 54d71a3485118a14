#pragma once
// Adding up the parts of a render split over machines: each part holds a sample range of a window
// of the picture (a Film's sums). The parts must cover every pixel's samples 0..N-1 exactly once,
// for one N; then their exact sums add to the sums of the render made in one go, and the merged
// film's mean is that render's picture, bit for bit.

#include "render/film.h"

#include <span>
#include <string>
#include <vector>

namespace raylab {

struct FilmPart {
    std::string name; // for messages (the file's name)
    FilmWindow window;
    uint32_t firstSample = 0; // samples [firstSample, endSample)
    uint32_t endSample = 0;
    std::span<const PixelSum> sums;     // window.width() x window.height(), row-major
    std::span<const glm::vec3> squares; // the same size, or empty
};

// Checks that the parts (their windows and ranges; sums and squares are not looked at) cover
// samples 0..N-1 of every pixel of a width x height picture exactly once, N the largest
// endSample. Returns an empty string with `samples` = N, or one line naming the first pixels whose
// samples are missing or given twice (and by which parts).
std::string checkFilmParts(int width, int height, std::span<const FilmPart> parts,
                           uint32_t& samples);

// The sums of a merge being made, part by part (a merge of many large parts holds one part at a
// time): start(), add() each part checkFilmParts accepted, then finish() into the film.
class FilmMerger {
public:
    FilmMerger(int width, int height, bool squares);
    void add(const FilmPart& part);
    // The film of the whole picture holding samples 0..samples-1: the added sums, and the added
    // squares when every part had them.
    void finish(uint32_t samples, Film& film);

private:
    int width_;
    int height_;
    bool squares_;
    std::vector<PixelSum> sums_;
    std::vector<glm::vec3> moments_;
};

// checkFilmParts, then every part added into `film` (reset to the whole picture, holding
// samples 0..N-1; its noise moments kept when every part has them). Returns an empty string, or
// one line naming the first pixels whose samples are missing or given twice (and by which
// parts), leaving `film` unspecified.
std::string mergeFilmParts(int width, int height, std::span<const FilmPart> parts, Film& film);

} // namespace raylab
