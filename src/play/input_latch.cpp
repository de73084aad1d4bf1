#include "play/input_latch.hpp"

#include <cstdint>

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
  if (slot(reported_, key) && slot(released_since_sample_, key)) slot(repressed_, key) = true;
  slot(held_, key) = true;
  slot(pressed_since_sample_, key) = true;
}

void InputLatch::release(DriveKey key) {
  slot(held_, key) = false;
  slot(released_since_sample_, key) = true;
}

void InputLatch::releaseAll() {
  held_ = {};
  pressed_since_sample_ = {};
  repressed_ = {};
  pending_ = {};
  released_since_sample_ = reported_;
}

InputFrame InputLatch::sample() {
  const std::uint8_t any = held_.bits() | pressed_since_sample_.bits() | pending_.bits();
  const InputFrame out = InputFrame::fromBits(static_cast<std::uint8_t>(any & ~repressed_.bits()));
  pending_ = repressed_;
  repressed_ = {};
  pressed_since_sample_ = {};
  released_since_sample_ = {};
  reported_ = out;
  return out;
}

}  // namespace cardemo
