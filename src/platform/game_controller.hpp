#pragma once
/// The first SDL game controller plugged in: opened and closed as it comes and goes, read as a
/// PadState once per drawn frame.

#include <SDL.h>

#include "play/analog_drive.hpp"

namespace cardemo {

/// Holds at most one SDL_GameController (the first one seen). The game works the same without.
class GameController {
 public:
  /// Opens the first controller already connected, if any (the game-controller subsystem must be
  /// initialised; when it is not, this object stays empty).
  GameController();
  ~GameController();
  GameController(const GameController&) = delete;
  GameController& operator=(const GameController&) = delete;

  /// Handles SDL_CONTROLLERDEVICEADDED / REMOVED; returns true when the event was one of them.
  bool handleDeviceEvent(const SDL_Event& event);
  /// True when `event` comes from the controller in use.
  [[nodiscard]] bool owns(SDL_JoystickID which) const;
  /// The stick, triggers and handbrake button (A) now; all zero without a controller.
  [[nodiscard]] PadState read() const;

 private:
  void open(int device_index);
  SDL_GameController* pad_ = nullptr;
  SDL_JoystickID id_ = -1;
};

}  // namespace cardemo
