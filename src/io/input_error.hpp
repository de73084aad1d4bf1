#pragma once
/// Errors in user input: file, line and one sentence. Returned as values, never thrown out of io/.

#include <string>
#include <utility>
#include <variant>

namespace cardemo {

/// A problem in an input file, reported as `FILE:LINE: message` (LINE omitted when 0).
struct InputError {
  std::string file;     ///< Path as the user gave it ("-" for standard input).
  int line = 0;         ///< 1-based line, or 0 when the input has no lines (e.g. unreadable file).
  std::string message;  ///< What is wrong, one sentence, no trailing period needed.

  /// `FILE:LINE: message`.
  [[nodiscard]] std::string toString() const {
    return file + ":" + (line > 0 ? std::to_string(line) + ": " : std::string(" ")) + message;
  }
};

/// Either a parsed value or the error that stopped parsing.
template <typename T>
class Parsed {
 public:
  /// Success.
  Parsed(T value) : v_(std::move(value)) {}  // NOLINT(google-explicit-constructor)
  /// Failure.
  Parsed(InputError error) : v_(std::move(error)) {}  // NOLINT(google-explicit-constructor)
  /// True on success.
  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(v_); }
  /// The value; only when ok().
  [[nodiscard]] const T& value() const& { return std::get<T>(v_); }
  /// The value, moved out; only when ok().
  [[nodiscard]] T&& value() && { return std::get<T>(std::move(v_)); }
  /// The error; only when !ok().
  [[nodiscard]] const InputError& error() const { return std::get<InputError>(v_); }

 private:
  std::variant<T, InputError> v_;
};

/// Reads a whole file (or standard input for "-"), refusing more than `max_bytes`.
[[nodiscard]] Parsed<std::string> readInputFile(const std::string& path, std::size_t max_bytes);

}  // namespace cardemo
