#pragma once
/// One tick of player input: the same data drives the window and the replays.

#include <cstdint>

namespace cardemo {

/// Keys held during one fixed step.
struct InputFrame {
  bool up = false;         ///< Throttle (brakes first when rolling backwards).
  bool down = false;       ///< Brake, then reverse once stopped.
  bool left = false;       ///< Steer left (counter-clockwise).
  bool right = false;      ///< Steer right (clockwise).
  bool handbrake = false;  ///< Handbrake: locks the rear wheels (an extension of U/D/L/R).

  /// Packs the keys into 5 bits: U=1, D=2, L=4, R=8, H (handbrake)=16.
  [[nodiscard]] std::uint8_t bits() const {
    return static_cast<std::uint8_t>((up ? 1 : 0) | (down ? 2 : 0) | (left ? 4 : 0) |
                                     (right ? 8 : 0) | (handbrake ? 16 : 0));
  }
  /// Inverse of bits().
  [[nodiscard]] static InputFrame fromBits(std::uint8_t b) {
    return {(b & 1) != 0, (b & 2) != 0, (b & 4) != 0, (b & 8) != 0, (b & 16) != 0};
  }
  /// Bitwise equality.
  [[nodiscard]] bool operator==(const InputFrame&) const = default;
};

}  // namespace cardemo
