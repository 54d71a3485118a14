#pragma once
// A partial render: the exact per-pixel sums of a range of samples of a window of a picture, with
// the settings that made them, written by `raylab-render --partial` and added up by
// `raylab-merge`. The file is an OpenEXR image that any viewer opens: its display window is the
// whole picture, its data window the pixels held, its R, G, B channels the unnormalised sums
// (float, for looking at). The exact sums (render/exact_sum.h) travel beside them as four 32-bit
// UINT channels per colour, raylab.R.0 (least significant word) .. raylab.R.3, and the noise
// moments as FLOAT channels raylab.R2 etc.; the header holds the sample range, the settings (the
// JSON of --save-settings), the scene's name and the hash of its file.

#include "core/render/film.h"

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

struct PartialRender {
    int imageWidth = 0; // the whole picture's size
    int imageHeight = 0;
    FilmWindow window;        // the pixels held
    uint32_t firstSample = 0; // samples [firstSample, endSample) of each pixel
    uint32_t endSample = 0;
    std::string settingsJson;       // settingsToJson(settings, scene)
    std::string scene;              // as given on the command line
    std::string sceneHash;          // sceneContentHash(scene)
    std::vector<PixelSum> sums;     // window.width() x window.height(), row-major from the top
    std::vector<glm::vec3> squares; // the same size, or empty (no noise moments)
    bool hasSquares = false;        // whether the file holds noise moments (read with its header)
};

// The partial of a film (its window, range and sums).
PartialRender partialOf(const Film& film, int imageWidth, int imageHeight);

// Writes the file atomically (whole or not at all). Returns false with one line in `error`.
bool writePartial(const std::string& path, const PartialRender& partial, std::string& error);
// Reads a file writePartial wrote; refuses anything else (a plain EXR, a window outside the
// picture, a bad range) with one line naming the file.
// What is read: the header alone (everything but sums and squares, which stay empty) or all.
enum class PartialRead { HeaderOnly, All };
bool readPartial(const std::string& path, PartialRender& partial, std::string& error,
                 PartialRead what = PartialRead::All);

// What identifies a scene's contents: "lab box" for the lab's built-in box, else the 64-bit
// FNV-1a hash of the file's bytes in hex. Returns false with one line when the file cannot be
// read.
bool sceneContentHash(const std::string& scene, std::string& hash, std::string& error);

} // namespace raylab
