// GameController: a virtual SDL game controller (no hardware, no display) read as a PadState with
// the documented layout, and handled as it is plugged in and out.

#include "platform/game_controller.hpp"

#include <gtest/gtest.h>

namespace cardemo {
namespace {

// A virtual controller with the standard layout: SDL maps its axes and buttons in
// SDL_GameControllerAxis / SDL_GameControllerButton order.
class VirtualPad : public ::testing::Test {
 protected:
  void SetUp() override {
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (SDL_Init(SDL_INIT_GAMECONTROLLER) != 0) GTEST_SKIP() << SDL_GetError();
    SDL_VirtualJoystickDesc desc{};
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
    desc.naxes = SDL_CONTROLLER_AXIS_MAX;
    desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
    device_ = SDL_JoystickAttachVirtualEx(&desc);
    ASSERT_GE(device_, 0) << SDL_GetError();
    joystick_ = SDL_JoystickOpen(device_);
    ASSERT_NE(joystick_, nullptr) << SDL_GetError();
  }
  void TearDown() override {
    if (joystick_ != nullptr) SDL_JoystickClose(joystick_);
    if (device_ >= 0) SDL_JoystickDetachVirtual(device_);
    SDL_Quit();
  }
  void set(SDL_GameControllerAxis axis, Sint16 value) {
    ASSERT_EQ(SDL_JoystickSetVirtualAxis(joystick_, axis, value), 0) << SDL_GetError();
  }
  void press(SDL_GameControllerButton button, bool down) {
    ASSERT_EQ(SDL_JoystickSetVirtualButton(joystick_, button, down ? 1 : 0), 0) << SDL_GetError();
  }
  static void update() { SDL_GameControllerUpdate(); }

  int device_ = -1;
  SDL_Joystick* joystick_ = nullptr;
};

TEST_F(VirtualPad, RestingPadReadsZero) {
  GameController pad;
  update();
  const PadState state = pad.read();
  EXPECT_EQ(state.steer, 0.0);
  EXPECT_EQ(state.throttle, 0.0);
  EXPECT_EQ(state.brake, 0.0);
  EXPECT_FALSE(state.handbrake);
}

TEST_F(VirtualPad, StickTriggersAndHandbrakeFollowTheLayout) {
  GameController pad;
  set(SDL_CONTROLLER_AXIS_LEFTX, -32768);
  set(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
  press(SDL_CONTROLLER_BUTTON_A, true);
  update();
  PadState state = pad.read();
  EXPECT_EQ(state.steer, -1.0);
  EXPECT_EQ(state.throttle, 1.0);
  EXPECT_EQ(state.brake, 0.0);
  EXPECT_TRUE(state.handbrake);

  set(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  // The virtual device's raw axis spans -32768..32767; SDL maps that onto the trigger's 0..32767.
  set(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, -32768);
  set(SDL_CONTROLLER_AXIS_LEFTY, 32767);  // stick pulled down: brake
  press(SDL_CONTROLLER_BUTTON_A, false);
  update();
  state = pad.read();
  EXPECT_EQ(state.steer, 1.0);
  EXPECT_EQ(state.throttle, 0.0);
  EXPECT_EQ(state.brake, 1.0);
  EXPECT_FALSE(state.handbrake);
}

TEST_F(VirtualPad, UnpluggedPadReadsZeroAndEventsAreOwned) {
  GameController pad;
  set(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
  update();
  EXPECT_EQ(pad.read().throttle, 1.0);
  const SDL_JoystickID id = SDL_JoystickInstanceID(joystick_);
  EXPECT_TRUE(pad.owns(id));
  EXPECT_FALSE(pad.owns(id + 1000));
  SDL_Event removed{};
  removed.type = SDL_CONTROLLERDEVICEREMOVED;
  removed.cdevice.which = id;
  EXPECT_TRUE(pad.handleDeviceEvent(removed));
  EXPECT_FALSE(pad.owns(id));
  EXPECT_EQ(pad.read().throttle, 0.0);
  SDL_Event added{};
  added.type = SDL_CONTROLLERDEVICEADDED;
  added.cdevice.which = device_;
  EXPECT_TRUE(pad.handleDeviceEvent(added));
  EXPECT_TRUE(pad.owns(id));
  SDL_Event other{};
  other.type = SDL_KEYDOWN;
  EXPECT_FALSE(pad.handleDeviceEvent(other));
}

}  // namespace
}  // namespace cardemo
