#pragma once
/// Incremental 64-bit FNV-1a over exact bit patterns (the determinism hash).

#include <cstdint>
#include <cstring>

namespace cardemo {

/// FNV-1a, 64-bit (Fowler, Noll, Vo; http://www.isthe.com/chongo/tech/comp/fnv/). Each value is
/// fed as 8 bytes, least significant first, so the hash does not depend on the host's byte order.
class Fnv1a64 {
 public:
  /// Feeds the 8 bytes of `v`.
  void add(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      hash_ ^= (v >> (8 * i)) & 0xffu;
      hash_ *= 1099511628211ull;
    }
  }
  /// Feeds a signed integer as its two's-complement 64-bit pattern.
  void addInt(std::int64_t v) { add(static_cast<std::uint64_t>(v)); }
  /// Feeds the exact bits of a double (so -0.0 and 0.0 differ).
  void addDouble(double d) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &d, sizeof bits);
    add(bits);
  }
  /// The hash so far.
  [[nodiscard]] std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace cardemo
