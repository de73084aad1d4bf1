#include "play/input_latch.hpp"

namespace cardemo {
namespace {

bool& slot(InputFrame& frame, DriveKey key) {
  switch (key) {
    case DriveKey::kUp:
      return frame.up;
    case DriveKey::kDown:
      return frame.down;
    case DriveKey::kLeft:
      return frame.left;
    case DriveKey::kRight:
      return frame.right;
    case DriveKey::kHandbrake:
      break;
  }
  return frame.handbrake;
}

}  // namespace

void InputLatch::press(DriveKey key) {
  slot(held_, key) = true;
  slot(pressed_since_sample_, key) = true;
}

void InputLatch::release(DriveKey key) {
  slot(held_, key) = false;
}

void InputLatch::releaseAll() {
  held_ = {};
  pressed_since_sample_ = {};
}

InputFrame InputLatch::sample() {
  const InputFrame out = InputFrame::fromBits(held_.bits() | pressed_since_sample_.bits());
  pressed_since_sample_ = {};
  return out;
}

}  // namespace cardemo
