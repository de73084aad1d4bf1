#include "play/analog_drive.hpp"

#include <algorithm>
#include <cmath>

namespace cardemo {

bool SigmaDelta::next(double level) {
  const double x = std::isnan(level) ? 0.0 : std::clamp(level, 0.0, 1.0);
  // Error feedback: emit "on" when the level owed so far reaches half a step.
  error_ += x;
  if (error_ >= 0.5) {
    error_ -= 1.0;
    return true;
  }
  return false;
}

double axisLevel(int raw, double dead_zone) {
  const double v = std::clamp(static_cast<double>(raw) / 32767.0, -1.0, 1.0);
  const double magnitude = std::abs(v);
  if (magnitude <= dead_zone) return 0.0;
  const double scaled = std::min(1.0, (magnitude - dead_zone) / (1.0 - dead_zone));
  return v < 0.0 ? -scaled : scaled;
}

PadState padFromAxes(int left_x, int left_y, int trigger_left, int trigger_right, bool handbrake) {
  PadState pad;
  pad.steer = axisLevel(left_x);
  const double stick_y = axisLevel(left_y);
  // Triggers rest at 0: a small dead zone only hides wear.
  pad.throttle = std::max(axisLevel(trigger_right, 0.05), std::max(0.0, -stick_y));
  pad.brake = std::max(axisLevel(trigger_left, 0.05), std::max(0.0, stick_y));
  pad.handbrake = handbrake;
  return pad;
}

InputFrame AnalogDrive::sample(const PadState& pad) {
  InputFrame out;
  out.up = up_.next(pad.throttle);
  out.down = down_.next(pad.brake);
  out.left = left_.next(-pad.steer);
  out.right = right_.next(pad.steer);
  out.handbrake = pad.handbrake;
  return out;
}

void AnalogDrive::reset() {
  up_.reset();
  down_.reset();
  left_.reset();
  right_.reset();
}

InputFrame mergeInputs(const InputFrame& a, const InputFrame& b) {
  return InputFrame::fromBits(static_cast<std::uint8_t>(a.bits() | b.bits()));
}

}  // namespace cardemo
