#include "platform/game_controller.hpp"

namespace cardemo {

GameController::GameController() {
  if (SDL_WasInit(SDL_INIT_GAMECONTROLLER) == 0) return;
  for (int i = 0; i < SDL_NumJoysticks() && pad_ == nullptr; ++i) open(i);
}

GameController::~GameController() {
  if (pad_ != nullptr) SDL_GameControllerClose(pad_);
}

void GameController::open(int device_index) {
  if (!SDL_IsGameController(device_index)) return;
  pad_ = SDL_GameControllerOpen(device_index);
  if (pad_ != nullptr) id_ = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pad_));
}

bool GameController::handleDeviceEvent(const SDL_Event& event) {
  if (event.type == SDL_CONTROLLERDEVICEADDED) {
    if (pad_ == nullptr) open(event.cdevice.which);  // `which` is a device index here
    return true;
  }
  if (event.type == SDL_CONTROLLERDEVICEREMOVED) {
    if (pad_ != nullptr && event.cdevice.which == id_) {  // and an instance id here
      SDL_GameControllerClose(pad_);
      pad_ = nullptr;
      id_ = -1;
    }
    return true;
  }
  return false;
}

bool GameController::owns(SDL_JoystickID which) const {
  return pad_ != nullptr && which == id_;
}

PadState GameController::read() const {
  if (pad_ == nullptr) return {};
  const auto axis = [this](SDL_GameControllerAxis a) {
    return static_cast<int>(SDL_GameControllerGetAxis(pad_, a));
  };
  return padFromAxes(axis(SDL_CONTROLLER_AXIS_LEFTX), axis(SDL_CONTROLLER_AXIS_LEFTY),
                     axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT), axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT),
                     SDL_GameControllerGetButton(pad_, SDL_CONTROLLER_BUTTON_A) != 0);
}

}  // namespace cardemo
