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

std::string checkFilmParts(int width, int height, std::span<const FilmPart> parts,
                           uint32_t& samples) {
    if (parts.empty()) {
        return "no parts to merge";
    }
    uint32_t total = 0;
    for (const FilmPart& part : parts) {
        const FilmWindow& w = part.window;
        if (w.x0 < 0 || w.y0 < 0 || w.x1 > width || w.y1 > height || w.width() < 1 ||
            w.height() < 1 || part.endSample <= part.firstSample) {
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
    samples = total;
    return {};
}

FilmMerger::FilmMerger(int width, int height, bool squares)
    : width_(width), height_(height), squares_(squares),
      sums_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)),
      moments_(squares ? sums_.size() : 0, glm::vec3(0.0f)) {}

void FilmMerger::add(const FilmPart& part) {
    const FilmWindow& w = part.window;
    const bool squares = squares_ && !part.squares.empty();
    for (int y = w.y0; y < w.y1; ++y) {
        for (int x = w.x0; x < w.x1; ++x) {
            const std::size_t from = static_cast<std::size_t>(y - w.y0) * w.width() + (x - w.x0);
            const std::size_t to = static_cast<std::size_t>(y) * width_ + x;
            sums_[to].add(part.sums[from]);
            if (squares) {
                moments_[to] += part.squares[from];
            }
        }
    }
}

void FilmMerger::finish(uint32_t samples, Film& film) {
    film.reset(width_, height_, FilmLayers{squares_, false});
    film.assign(sums_, 0, samples);
    std::copy(moments_.begin(), moments_.end(), film.squares().begin());
}

std::string mergeFilmParts(int width, int height, std::span<const FilmPart> parts, Film& film) {
    uint32_t samples = 0;
    if (std::string why = checkFilmParts(width, height, parts, samples); !why.empty()) {
        return why;
    }
    for (const FilmPart& part : parts) {
        if (part.sums.size() != static_cast<std::size_t>(part.window.width()) *
                                    static_cast<std::size_t>(part.window.height())) {
            return part.name + ": its window or range does not fit the picture";
        }
    }
    const bool squares = std::all_of(parts.begin(), parts.end(),
                                     [](const FilmPart& p) { return !p.squares.empty(); });
    // Parts in order of their first sample, so that the float moments add in one order too.
    std::vector<const FilmPart*> ordered;
    for (const FilmPart& part : parts) {
        ordered.push_back(&part);
    }
    std::stable_sort(ordered.begin(), ordered.end(), [](const FilmPart* a, const FilmPart* b) {
        return a->firstSample < b->firstSample;
    });
    FilmMerger merger(width, height, squares);
    for (const FilmPart* part : ordered) {
        merger.add(*part);
    }
    merger.finish(samples, film);
    return {};
}

} // namespace raylab
