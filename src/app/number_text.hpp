#pragma once
/// Shortest text that reads back to the same double (exact, locale-free).

#include <charconv>
#include <string>

namespace cardemo::app {

/// Shortest round-trip decimal form of `value`.
inline std::string numberText(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return {buffer, result.ptr};
}

/// `value` with a fixed number of decimals, for human-readable tables.
inline std::string fixedText(double value, int decimals) {
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
  return {buffer, result.ptr};
}

}  // namespace cardemo::app
