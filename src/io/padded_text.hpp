#pragma once
/// Text in memory followed by zero bytes that a vectorised parser (simdjson) may read past its end.

#include <cstddef>
#include <string>
#include <string_view>

#include "io/input_error.hpp"

namespace cardemo {

/// Bytes in their own memory, followed by kPadding readable zero bytes. Move-only.
class PaddedText {
 public:
  /// Zero bytes readable after the end of the text (simdjson's SIMDJSON_PADDING).
  static constexpr std::size_t kPadding = 64;

  /// Empty (still padded).
  PaddedText() = default;
  /// A padded copy of `text`.
  [[nodiscard]] static PaddedText copyOf(std::string_view text);
  /// Takes the memory of `other`, which is left empty.
  PaddedText(PaddedText&& other) noexcept;
  /// Takes the memory of `other`, which is left empty.
  PaddedText& operator=(PaddedText&& other) noexcept;
  PaddedText(const PaddedText&) = delete;
  PaddedText& operator=(const PaddedText&) = delete;
  /// Frees the memory.
  ~PaddedText();

  /// The text, without the padding.
  [[nodiscard]] std::string_view view() const { return {buffer_ ? buffer_ : kEmpty, size_}; }

 private:
  friend Parsed<PaddedText> readPaddedFile(const std::string& path, std::size_t max_bytes);
  // `size` zero bytes to fill (buffer_), then the padding.
  explicit PaddedText(std::size_t size);
  void release() noexcept;

  static constexpr char kEmpty[kPadding] = {};
  char* buffer_ = nullptr;   // the text, inside the mapping; nullptr when empty
  std::size_t size_ = 0;     // bytes of text
  void* mapping_ = nullptr;  // what mmap returned, or nullptr
  std::size_t mapped_bytes_ = 0;
};

/// Reads a whole file (or standard input for "-") into padded memory, refusing more than
/// `max_bytes`, with the errors of readInputFile.
[[nodiscard]] Parsed<PaddedText> readPaddedFile(const std::string& path, std::size_t max_bytes);

}  // namespace cardemo
