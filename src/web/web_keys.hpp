#pragma once
/// The page's keys: KeyboardEvent.code names (physical positions) to the game's GameKey.

#include <optional>
#include <string_view>

#include "play/key_map.hpp"

namespace cardemo {

/// The GameKey of a KeyboardEvent.code (e.g. "ArrowUp", "KeyW", "Space", "F1"), if the game reads
/// it. F11 and F12 are left to the browser (its own full screen and developer tools).
[[nodiscard]] std::optional<GameKey> gameKeyOfCode(std::string_view code);

/// The GameKey of a KeyboardEvent.key for the keys whose symbol matters more than their place
/// (+ and - on layouts where they sit elsewhere), if any.
[[nodiscard]] std::optional<GameKey> gameKeyOfSymbol(std::string_view key);

}  // namespace cardemo
