#pragma once
// Small string helpers shared by the io files (ASCII only; no locale).

#include <filesystem>
#include <string>
#include <string_view>

namespace raylab {

inline bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

// `text` without leading and trailing ASCII white space.
inline std::string trim(std::string_view text) {
    while (!text.empty() && isSpace(text.front())) {
        text.remove_prefix(1);
    }
    while (!text.empty() && isSpace(text.back())) {
        text.remove_suffix(1);
    }
    return std::string(text);
}

// ASCII lower case (file extensions, option values).
inline std::string lowerCase(std::string text) {
    for (char& c : text) {
        if (c >= 'A' && c <= 'Z') {
            c = static_cast<char>(c - 'A' + 'a');
        }
    }
    return text;
}

// A path's extension in lower case, with its dot (".png"); empty when it has none.
inline std::string extensionOf(const std::string& path) {
    return lowerCase(std::filesystem::path(path).extension().string());
}

// `text` made fit for one line of a message: line breaks, tabs and other control characters (a
// file's contents, a key or an option the user typed) become \n, \t or \xNN.
inline std::string singleLine(std::string_view text) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (u < 0x20 || u == 0x7f) {
            out += "\\x";
            out += kHex[u >> 4];
            out += kHex[u & 15];
        } else {
            out += c;
        }
    }
    return out;
}

// The message of nlohmann::json's parse exception (e.what()) for a user: "invalid JSON: parse
// error at line 1, column 2: ..." without the library's "[json.exception.parse_error.101] " tag,
// on one line.
inline std::string jsonParseError(std::string what) {
    if (const auto tagEnd = what.find("] ");
        what.rfind("[json.", 0) == 0 && tagEnd != std::string::npos) {
        what = what.substr(tagEnd + 2);
    }
    return "invalid JSON: " + singleLine(what);
}

// Makes `error` singleLine() when the scope ends: the first statement of a function whose every
// error, whatever text it quotes, must be one line.
class SingleLineOnExit {
public:
    explicit SingleLineOnExit(std::string& error) : error_(error) {}
    ~SingleLineOnExit() { error_ = singleLine(error_); }
    SingleLineOnExit(const SingleLineOnExit&) = delete;
    SingleLineOnExit& operator=(const SingleLineOnExit&) = delete;

private:
    std::string& error_;
};

} // namespace raylab
