#include "platform/sdl_keys.hpp"

namespace cardemo {
namespace {

std::optional<GameKey> byPosition(SDL_Scancode code) {
  switch (code) {
    case SDL_SCANCODE_UP:
      return GameKey::kUp;
    case SDL_SCANCODE_DOWN:
      return GameKey::kDown;
    case SDL_SCANCODE_LEFT:
      return GameKey::kLeft;
    case SDL_SCANCODE_RIGHT:
      return GameKey::kRight;
    case SDL_SCANCODE_W:
      return GameKey::kW;
    case SDL_SCANCODE_A:
      return GameKey::kA;
    case SDL_SCANCODE_S:
      return GameKey::kS;
    case SDL_SCANCODE_D:
      return GameKey::kD;
    case SDL_SCANCODE_SPACE:
      return GameKey::kSpace;
    default:
      return std::nullopt;
  }
}

std::optional<GameKey> bySymbol(SDL_Keycode sym) {
  switch (sym) {
    case SDLK_RETURN:
      return GameKey::kEnter;
    case SDLK_KP_ENTER:
      return GameKey::kKeypadEnter;
    case SDLK_ESCAPE:
      return GameKey::kEscape;
    case SDLK_p:
      return GameKey::kP;
    case SDLK_n:
      return GameKey::kN;
    case SDLK_r:
      return GameKey::kR;
    case SDLK_b:
      return GameKey::kB;
    case SDLK_m:
      return GameKey::kM;
    case SDLK_F1:
      return GameKey::kF1;
    case SDLK_F11:
      return GameKey::kF11;
    case SDLK_F12:
      return GameKey::kF12;
    case SDLK_PLUS:
      return GameKey::kPlus;
    case SDLK_EQUALS:
      return GameKey::kEquals;
    case SDLK_KP_PLUS:
      return GameKey::kKeypadPlus;
    case SDLK_MINUS:
      return GameKey::kMinus;
    case SDLK_KP_MINUS:
      return GameKey::kKeypadMinus;
    case SDLK_LEFTBRACKET:
      return GameKey::kLeftBracket;
    case SDLK_RIGHTBRACKET:
      return GameKey::kRightBracket;
    default:
      return std::nullopt;
  }
}

}  // namespace

std::optional<GameKey> gameKeyOf(const SDL_Keysym& key) {
  if (const std::optional<GameKey> positional = byPosition(key.scancode)) return positional;
  return bySymbol(key.sym);
}

std::optional<PadButton> padButtonOf(Uint8 button) {
  switch (button) {
    case SDL_CONTROLLER_BUTTON_DPAD_UP:
      return PadButton::kDpadUp;
    case SDL_CONTROLLER_BUTTON_DPAD_DOWN:
      return PadButton::kDpadDown;
    case SDL_CONTROLLER_BUTTON_DPAD_LEFT:
      return PadButton::kDpadLeft;
    case SDL_CONTROLLER_BUTTON_DPAD_RIGHT:
      return PadButton::kDpadRight;
    case SDL_CONTROLLER_BUTTON_START:
      return PadButton::kStart;
    case SDL_CONTROLLER_BUTTON_A:
      return PadButton::kA;
    case SDL_CONTROLLER_BUTTON_BACK:
      return PadButton::kBack;
    default:
      return std::nullopt;
  }
}

}  // namespace cardemo
