#include "render/film_merge.h"

#include <algorithm>
#include <vector>

namespace raylab {
namespace {

std::string rectText(int x0, int y0, int x1, int y1) {
    return "pixels " + std::to_string(x0) + "," + std::to_string(y0) + " to " + std::to_string(x1) +
           "," + std::to_string(y1);
}

std::string rangeText(uint32_t a, uint32_t b) {
    return "samples " + std::to_string(a) + ":" + std::to_string(b);
}

} // namespace

std::string mergeFilmParts(int width, int height, std::span<const FilmPart> parts, Film& film) {
    if (parts.empty()) {
        return "no parts to merge";
    }
    uint32_t total = 0;
    for (const FilmPart& part : parts) {
        const FilmWindow& w = part.window;
        if (w.x0 < 0 || w.y0 < 0 || w.x1 > width || w.y1 > height || w.width() < 1 ||
            w.height() < 1 || part.endSample <= part.firstSample ||
            part.sums.size() != static_cast<std::size_t>(w.width()) * w.height()) {
            return part.name + ": its window or range does not fit the picture";
        }
        total = std::max(total, part.endSample);
    }
    // The picture cut at every window's edges: within a cell, every pixel is in the same parts.
    std::vector<int> xs{0, width};
    std::vector<int> ys{0, height};
    for (const FilmPart& part : parts) {
        xs.insert(xs.end(), {part.window.x0, part.window.x1});
        ys.insert(ys.end(), {part.window.y0, part.window.y1});
    }
    for (std::vector<int>* edges : {&xs, &ys}) {
        std::sort(edges->begin(), edges->end());
        edges->erase(std::unique(edges->begin(), edges->end()), edges->end());
    }
    std::vector<const FilmPart*> covering;
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
        for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
            const std::string where = rectText(xs[i], ys[j], xs[i + 1], ys[j + 1]);
            covering.clear();
            for (const FilmPart& part : parts) {
                if (part.window.x0 <= xs[i] && xs[i + 1] <= part.window.x1 &&
                    part.window.y0 <= ys[j] && ys[j + 1] <= part.window.y1) {
                    covering.push_back(&part);
                }
            }
            std::sort(covering.begin(), covering.end(), [](const FilmPart* a, const FilmPart* b) {
                return a->firstSample < b->firstSample;
            });
            uint32_t next = 0;
            for (const FilmPart* part : covering) {
                if (part->firstSample < next) {
                    return rangeText(part->firstSample, std::min(next, part->endSample)) + " of " +
                           where + " are in two parts (" + part->name + " and another)";
                }
                if (part->firstSample > next) {
                    return rangeText(next, part->firstSample) + " of " + where + " are missing";
                }
                next = part->endSample;
            }
            if (next < total) {
                return rangeText(next, total) + " of " + where + " are missing";
            }
        }
    }

    const bool squares = std::all_of(parts.begin(), parts.end(),
                                     [](const FilmPart& p) { return !p.squares.empty(); });
    film.reset(width, height, FilmLayers{squares, false});
    std::vector<PixelSum> sums(film.pixelCount());
    std::vector<glm::vec3> moments(squares ? film.pixelCount() : 0, glm::vec3(0.0f));
    // Parts in order of their first sample, so that the float moments add in one order too.
    std::vector<const FilmPart*> ordered;
    for (const FilmPart& part : parts) {
        ordered.push_back(&part);
    }
    std::stable_sort(ordered.begin(), ordered.end(), [](const FilmPart* a, const FilmPart* b) {
        return a->firstSample < b->firstSample;
    });
    for (const FilmPart* part : ordered) {
        const FilmWindow& w = part->window;
        for (int y = w.y0; y < w.y1; ++y) {
            for (int x = w.x0; x < w.x1; ++x) {
                const std::size_t from =
                    static_cast<std::size_t>(y - w.y0) * w.width() + (x - w.x0);
                const std::size_t to = film.indexOf(x, y);
                sums[to].add(part->sums[from]);
                if (squares) {
                    moments[to] += part->squares[from];
                }
            }
        }
    }
    film.assign(sums, 0, total);
    std::copy(moments.begin(), moments.end(), film.squares().begin());
    return {};
}

} // namespace raylab
