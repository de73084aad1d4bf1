#pragma once
/// The input frames the simulation tests drive with: no keys, or one key held.

#include "sim/input_frame.hpp"

namespace cardemo::testing {

inline constexpr InputFrame kNone{};                                       ///< No key.
inline constexpr InputFrame kUp{true, false, false, false};                ///< Throttle.
inline constexpr InputFrame kDown{false, true, false, false};              ///< Brake, then reverse.
inline constexpr InputFrame kLeft{false, false, true, false};              ///< Steer left.
inline constexpr InputFrame kRight{false, false, false, true};             ///< Steer right.
inline constexpr InputFrame kHandbrake{false, false, false, false, true};  ///< Handbrake.

}  // namespace cardemo::testing
