#pragma once
// Strict parsing of command-line numbers: the whole text must be one number (std::from_chars, so
// no locale, no leading '+' or spaces, no hex), finite and representable.

#include <charconv>
#include <cmath>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>

namespace raylab {

inline bool parseFloat(std::string_view text, float& value) {
    const char* end = text.data() + text.size();
    float v = 0.0f;
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) {
        return false;
    }
    value = v;
    return true;
}

inline bool parseInt(std::string_view text, int& value) {
    const char* end = text.data() + text.size();
    int v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc() || ptr != end) {
        return false;
    }
    value = v;
    return true;
}

// "x,y,z": exactly three finite floats separated by commas (spaces around them are allowed).
inline bool parseVec3(std::string_view text, glm::vec3& value) {
    glm::vec3 v(0.0f);
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text.find(',');
        if ((i < 2) == (comma == std::string_view::npos)) {
            return false; // too few or too many components
        }
        std::string_view part = text.substr(0, comma);
        while (!part.empty() && part.front() == ' ') {
            part.remove_prefix(1);
        }
        while (!part.empty() && part.back() == ' ') {
            part.remove_suffix(1);
        }
        if (!parseFloat(part, v[i])) {
            return false;
        }
        text = i < 2 ? text.substr(comma + 1) : std::string_view();
    }
    value = v;
    return true;
}

} // namespace raylab
