#pragma once
/// Helpers shared by the io tests.

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "io/input_error.hpp"

namespace cardemo::testing {

/// `text` with the single occurrence of `from` replaced by `to` (fails the test if not exactly
/// one).
inline std::string replaced(std::string text, std::string_view from, std::string_view to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "missing: " << from;
  if (at == std::string::npos) return text;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "not unique: " << from;
  return text.replace(at, from.size(), to);
}

/// Asserts that `parsed` failed on `line` with a message containing `phrase`.
template <typename T>
::testing::AssertionResult failsAt(const Parsed<T>& parsed, int line, std::string_view phrase) {
  if (parsed.ok()) return ::testing::AssertionFailure() << "parsed without error";
  const InputError& e = parsed.error();
  if (e.line != line || e.message.find(phrase) == std::string::npos) {
    return ::testing::AssertionFailure() << "got " << e.toString() << "; wanted line " << line
                                         << " containing \"" << phrase << "\"";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace cardemo::testing
