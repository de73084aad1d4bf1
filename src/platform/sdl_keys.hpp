#pragma once
/// SDL's keys and controller buttons named as the game names them (play/key_map says what each
/// one does).

#include <SDL.h>

#include <optional>

#include "play/key_map.hpp"

namespace cardemo {

/// The GameKey of an SDL key: the arrows, W, A, S, D and Space by position (scancode), so the
/// same physical keys drive on any layout; the others by symbol. nullopt for a key the game does
/// not read.
[[nodiscard]] std::optional<GameKey> gameKeyOf(const SDL_Keysym& key);

/// The PadButton of an SDL game-controller button, or nullopt for one the game does not read.
[[nodiscard]] std::optional<PadButton> padButtonOf(Uint8 button);

}  // namespace cardemo
