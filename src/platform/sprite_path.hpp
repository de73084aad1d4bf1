#pragma once
/// Finding the folder of sprites (assets/sprites) the window and `render --sprites` draw with.

#include <optional>
#include <string>

namespace cardemo {

/// Folder holding car.png: $CARDEMO_SPRITES when set, else assets/sprites under the working
/// folder, else the source tree's assets/sprites. Returns nullopt and sets `why` (one sentence)
/// when none holds the sprites.
[[nodiscard]] std::optional<std::string> findSpriteDir(std::string* why = nullptr);

}  // namespace cardemo
