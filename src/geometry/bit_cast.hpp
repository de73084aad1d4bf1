#pragma once
/// bitCast: the bits of a value read as another type of the same size (std::bit_cast's job; the
/// libc++ of emscripten 3.1.6, which the browser build uses, has no std::bit_cast).

#include <type_traits>

namespace cardemo {

/// The object representation of `from` read as a `To` of the same size, as std::bit_cast does.
template <class To, class From>
requires(sizeof(To) == sizeof(From) && std::is_trivially_copyable_v<To> &&
         std::is_trivially_copyable_v<From>) [[nodiscard]] constexpr To
    bitCast(const From& from) noexcept {
  // The builtin behind std::bit_cast in both GCC and Clang: constexpr, no copy through memory.
  return __builtin_bit_cast(To, from);
}

}  // namespace cardemo
