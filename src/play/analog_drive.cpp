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

bool AnalogDrive::pedal(SigmaDelta& modulator, Squeeze& squeeze, double level, bool against) {
  if (!(level > 0.0)) {
    squeeze = Squeeze::kNone;
    return modulator.next(0.0);
  }
  if (squeeze == Squeeze::kNone) squeeze = against ? Squeeze::kBrakes : Squeeze::kDrives;
  // A braking squeeze holds nothing once the car no longer moves against it: a pulse that began at
  // a standstill would be a fresh press, which drives the other way.
  if (squeeze == Squeeze::kBrakes && !against) return modulator.next(0.0);
  return modulator.next(level);
}

InputFrame AnalogDrive::sample(const PadState& pad, const World& world) {
  const double speed = world.car().speed;
  InputFrame out;
  out.up = pedal(up_, up_squeeze_, pad.throttle, speed < 0.0);
  out.down = pedal(down_, down_squeeze_, pad.brake, speed > 0.0);
  out.handbrake = pad.handbrake;
  // The wheel angle the stick asks for (left positive), and the key that steers nearest to it; on
  // a tie no key, so a centred stick never fights the keyboard.
  const double steer = std::isnan(pad.steer) ? 0.0 : std::clamp(pad.steer, -1.0, 1.0);
  const double aim = -steer * effectiveLock(world.carParams(), speed, pad.handbrake);
  InputFrame best = out;
  double best_error = std::abs(world.steerAfter(out) - aim);
  for (const bool left : {true, false}) {
    InputFrame keys = out;
    keys.left = left;
    keys.right = !left;
    const double error = std::abs(world.steerAfter(keys) - aim);
    if (error < best_error) {
      best = keys;
      best_error = error;
    }
  }
  return best;
}

void AnalogDrive::reset() {
  up_.reset();
  down_.reset();
  up_squeeze_ = Squeeze::kNone;
  down_squeeze_ = Squeeze::kNone;
}

InputFrame mergeInputs(const InputFrame& a, const InputFrame& b) {
  return InputFrame::fromBits(static_cast<std::uint8_t>(a.bits() | b.bits()));
}

}  // namespace cardemo
