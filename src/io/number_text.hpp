#pragma once
/// Decimal text of doubles, both ways, with the same characters on every platform: the shortest
/// text that reads back to the same double, text with a fixed number of decimals, and a strict
/// reader.
///
/// They give exactly what std::to_chars and std::from_chars give (tests/io compares them on many
/// seeded random doubles), but are built on snprintf and strtod, which glibc and musl both round
/// exactly: the libc++ of emscripten 3.1.6, which the browser build uses, has no floating-point
/// to_chars or from_chars.

#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>

namespace cardemo {

/// Shortest decimal text that reads back to `value`, the characters std::to_chars(value) writes:
/// fixed or scientific, whichever is shorter (fixed on a tie); "inf", "-inf", "nan", "-nan".
[[nodiscard]] std::string numberText(double value);

/// `value` rounded to `decimals` (>= 0) digits after the point, as
/// std::to_chars(value, std::chars_format::fixed, decimals) writes it.
[[nodiscard]] std::string fixedText(double value, int decimals);

/// What readNumber found at the start of a text.
struct NumberRead {
  std::size_t length = 0;  ///< Characters that form the number (0 when there is none).
  std::errc error{};       ///< {} on success, invalid_argument or result_out_of_range.
};

/// Reads the number that starts `text` as std::from_chars(first, last, value) does: an optional
/// '-', then decimal digits with an optional point and exponent, or "inf", "infinity", "nan",
/// "nan(...)" in any case; no '+', no leading blank, no hexadecimal. A value that overflows, or a
/// non-zero one that rounds to zero, is result_out_of_range. `value` is set only on success.
NumberRead readNumber(std::string_view text, double& value);

}  // namespace cardemo
