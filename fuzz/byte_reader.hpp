#pragma once
/// Decodes fuzz bytes, front to back, into the numbers the shape decoders need. Past the end of the
/// input every read gives 0, so every input decodes to something and short inputs stay simple.

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace cardemo::fuzz {

/// Sequential little-endian reader over the fuzz input.
class ByteReader {
 public:
  /// Reads `size` bytes at `data`, which must outlive the reader.
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  /// Next byte, or 0 past the end.
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  /// Next 4 bytes as an unsigned integer.
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= static_cast<std::uint32_t>(byte()) << (8 * k);
    return v;
  }
  /// Next 8 bytes as an unsigned integer.
  std::uint64_t u64() {
    const std::uint64_t low = u32();
    return low | (static_cast<std::uint64_t>(u32()) << 32);
  }
  /// A choice among `n` options (one byte).
  int pick(int n) { return byte() % n; }
  /// +1 or -1 (one byte).
  double sign() { return (byte() & 1) != 0 ? -1.0 : 1.0; }
  /// In [0, 1] with 53 significant bits (8 bytes), so values land between any two doubles.
  double unit() { return static_cast<double>(u64() >> 11) / 9007199254740991.0; }
  /// In [lo, hi].
  double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
  /// Log-uniform in [lo, hi], 0 < lo < hi (denormal lo allowed).
  double logRange(double lo, double hi) {
    const double v = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * unit());
    return v < lo ? lo : v > hi ? hi : v;
  }
  /// sign() times logRange(lo, hi), read in that order.
  double signedLog(double lo, double hi) {
    const double s = sign();
    return s * logRange(lo, hi);
  }
  /// sign() times range(lo, hi) rounded to a multiple of 2^-10 (sums of such values are exact).
  double dyadic(double lo, double hi) {
    const double s = sign();
    return s * std::ldexp(std::round(std::ldexp(range(lo, hi), 10)), -10);
  }
  /// True when every input byte has been read.
  [[nodiscard]] bool exhausted() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace cardemo::fuzz
