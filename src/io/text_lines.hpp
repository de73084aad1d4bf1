#pragma once
/// Line splitting and trimming shared by the text parsers (private to io/).

#include <cstddef>
#include <string>
#include <string_view>

namespace cardemo::text {

/// Yields the lines of a text in order, without '\n' and without one trailing '\r'.
class LineReader {
 public:
  /// Reads from `text`, which must outlive the reader.
  explicit LineReader(std::string_view text) : text_(text) {}

  /// Next line into `line`; false at the end. Linear in the text, whatever the line lengths.
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    return true;
  }

  /// 1-based number of the line last returned.
  [[nodiscard]] int number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int number_ = 0;
};

/// True for space and tab.
[[nodiscard]] inline bool isBlank(char c) {
  return c == ' ' || c == '\t';
}

/// `s` without leading and trailing spaces and tabs.
[[nodiscard]] inline std::string_view trim(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

/// Position of the first control byte (below 0x20 except tab, or 0x7f), or npos.
[[nodiscard]] inline std::size_t findControl(std::string_view s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto u = static_cast<unsigned char>(s[i]);
    if ((u < 0x20 && u != '\t') || u == 0x7f) return i;
  }
  return std::string_view::npos;
}

}  // namespace cardemo::text
