#pragma once
/// The colours the HUD, the end panels and the scene picker share.

#include "render/canvas.hpp"

namespace cardemo::hud_colors {

inline constexpr Rgba kPanel{12, 14, 18, 190};  ///< Panel background (translucent).
inline constexpr Rgba kText{235, 238, 242};     ///< Main text.
inline constexpr Rgba kDim{160, 168, 178};      ///< Secondary text.

}  // namespace cardemo::hud_colors
