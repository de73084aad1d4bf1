#pragma once
/// What every fuzz target uses: a failed property aborts with a message (libFuzzer then saves the
/// input as a crash), and the checks shared by the parser targets.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "io/input_error.hpp"

namespace cardemo::fuzz {

/// Aborts with `what` on stderr when `ok` is false: a broken property is a crash for libFuzzer.
inline void require(bool ok, const std::string& what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz property failed: %s\n", what.c_str());
  std::abort();
}

/// The input bytes as text.
[[nodiscard]] inline std::string_view asText(const unsigned char* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Number of lines a message may point at: one per '\n', plus the last (possibly empty) line.
[[nodiscard]] inline int lineCount(std::string_view text) {
  int lines = 1;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  return lines;
}

/// A parse error must name the file, carry a line inside the input, and print as one line of
/// printable ASCII (`FILE:LINE: message`), so a hostile file cannot forge extra output lines or
/// send terminal escapes.
inline void requireGoodError(const InputError& e, std::string_view text, const std::string& file) {
  const std::string shown = e.toString();
  require(e.file == file, "error names file '" + e.file + "': " + shown);
  require(e.line >= 1 && e.line <= lineCount(text), "error line out of range: " + shown);
  require(!e.message.empty(), "empty error message: " + shown);
  for (const char c : e.message) {
    const auto u = static_cast<unsigned char>(c);
    require(u >= 0x20 && u < 0x7f, "non-printable byte in the error message: " + shown);
  }
}

}  // namespace cardemo::fuzz
