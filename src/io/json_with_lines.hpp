#pragma once
/// A small JSON tree that remembers the source line of every value and key (private to io/).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "io/printable.hpp"

namespace cardemo::json_lines {

struct Member;

/// One JSON value and the 1-based line where it is written.
struct Node {
  /// What the value is.
  enum class Kind : std::uint8_t { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;      ///< Type of the value.
  bool boolean = false;         ///< Value when kBool.
  int line = 0;                 ///< Line of the value (of its opening bracket for containers).
  double number = 0.0;          ///< Value when kNumber (integers are converted).
  std::string text;             ///< Value when kString.
  std::vector<Node> items;      ///< Elements when kArray.
  std::vector<Member> members;  ///< Members in source order when kObject (keys are unique).

  /// The member named `key`, or nullptr.
  [[nodiscard]] const Node* find(std::string_view key) const;
};

/// An object member: key, the line of the key, and the value.
struct Member {
  std::string key;  ///< Key as decoded.
  int line = 0;     ///< Line of the key.
  Node value;       ///< The value.
};

/// A syntax or structure error found while reading the JSON text.
struct SyntaxError {
  int line = 1;         ///< 1-based line.
  std::string message;  ///< One sentence, printable ASCII.
};

/// Deepest nesting of arrays and objects accepted.
inline constexpr int kMaxDepth = 64;
/// Most values accepted in one document (bounds memory for hostile input).
inline constexpr std::size_t kMaxValues = std::size_t{1} << 24;

/// Parses strict JSON (no comments, no NaN/Infinity, no duplicate keys, no trailing data).
[[nodiscard]] std::variant<Node, SyntaxError> parse(std::string_view text);

/// "a number", "an object", ... for messages.
[[nodiscard]] const char* kindName(Node::Kind kind);

/// The byte escaper for messages (io/printable).
using cardemo::printable;

}  // namespace cardemo::json_lines
