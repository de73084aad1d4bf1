#include "web/web_keys.hpp"

#include <array>
#include <utility>

namespace cardemo {

std::optional<GameKey> gameKeyOfCode(std::string_view code) {
  static constexpr std::array<std::pair<std::string_view, GameKey>, 24> kCodes{{
      {"ArrowUp", GameKey::kUp},
      {"ArrowDown", GameKey::kDown},
      {"ArrowLeft", GameKey::kLeft},
      {"ArrowRight", GameKey::kRight},
      {"KeyW", GameKey::kW},
      {"KeyA", GameKey::kA},
      {"KeyS", GameKey::kS},
      {"KeyD", GameKey::kD},
      {"Space", GameKey::kSpace},
      {"Enter", GameKey::kEnter},
      {"NumpadEnter", GameKey::kKeypadEnter},
      {"Escape", GameKey::kEscape},
      {"KeyP", GameKey::kP},
      {"KeyN", GameKey::kN},
      {"KeyR", GameKey::kR},
      {"KeyB", GameKey::kB},
      {"KeyM", GameKey::kM},
      {"F1", GameKey::kF1},
      {"Equal", GameKey::kEquals},
      {"NumpadAdd", GameKey::kKeypadPlus},
      {"Minus", GameKey::kMinus},
      {"NumpadSubtract", GameKey::kKeypadMinus},
      {"BracketLeft", GameKey::kLeftBracket},
      {"BracketRight", GameKey::kRightBracket},
  }};
  for (const auto& [name, key] : kCodes) {
    if (name == code) return key;
  }
  return std::nullopt;
}

std::optional<GameKey> gameKeyOfSymbol(std::string_view key) {
  if (key == "+") return GameKey::kPlus;
  if (key == "-") return GameKey::kMinus;
  return std::nullopt;
}

}  // namespace cardemo
