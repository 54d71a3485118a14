#pragma once
// What every input surface of raylab promises, as checks one fuzz input at a time (shared by the
// libFuzzer targets and the corpus replay test in tests/io): the reader either accepts the input
// with a result that holds its invariants, or refuses it with one non-empty line. Each returns an
// empty string when the reader behaved, otherwise what it did wrong.

#include <cstddef>
#include <cstdint>
#include <string>

namespace raylab::fuzz {

// A partial render file (raylab-merge's input).
std::string checkPartialFile(const uint8_t* data, std::size_t size);
// Settings JSON text (--settings, and the raylab-settings chunk of a dropped screenshot), and
// the same text as a session recording (--replay); an accepted one must also survive a write
// and read back unchanged.
std::string checkSettingsJson(const uint8_t* data, std::size_t size);
// A session recording's JSON text (--replay), the part of checkSettingsJson that reads it.
std::string checkRecording(const std::string& text);
// A command line of raylab-render, raylab or raylab-bench (the first byte picks the program;
// arguments are the rest split at zero bytes).
std::string checkCommandLine(const uint8_t* data, std::size_t size);
// A PFM or EXR picture (--reference; the first byte picks the format).
std::string checkLinearImage(const uint8_t* data, std::size_t size);
// A PNG dropped on the viewer as a screenshot to restore (readScreenshotSettings: the PNG and its
// "raylab-settings" chunk); accepted settings must pass validate().
std::string checkScreenshotPng(const uint8_t* data, std::size_t size);

} // namespace raylab::fuzz
