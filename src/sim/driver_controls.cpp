#include "sim/driver_controls.hpp"

#include <algorithm>
#include <cstdlib>

namespace cardemo {
namespace {

// The kind of a pedal's press at a step: a press that begins now brakes when the car moves
// against the pedal (`against`), else drives; one already in progress keeps its kind.
PedalPress pressOf(PedalPress before, bool held, bool against) {
  if (!held) return PedalPress::kReleased;
  if (before != PedalPress::kReleased) return before;
  return against ? PedalPress::kBrakes : PedalPress::kDrives;
}

// Moves `value` toward `target` by at most `max_delta`, landing exactly on the target.
double stepToward(double value, double target, double max_delta) {
  if (value < target) return std::min(value + max_delta, target);
  if (value > target) return std::max(value - max_delta, target);
  return value;
}

}  // namespace

char gearLetter(Gear gear) {
  switch (gear) {
    case Gear::kDrive:
      return 'D';
    case Gear::kReverse:
      return 'R';
    case Gear::kNeutral:
      break;
  }
  return 'N';
}

DriverControls advanceControls(const DriverControls& before, const InputFrame& keys, double speed) {
  DriverControls next;
  next.up = pressOf(before.up, keys.up, speed < 0.0);
  next.down = pressOf(before.down, keys.down, speed > 0.0);
  if (keys.left != keys.right) {
    const std::int64_t side = keys.left ? 1 : -1;
    next.steer_steps = before.steer_steps * side > 0 ? before.steer_steps + side : side;
  }
  return next;
}

InputFrame pedalCommand(const DriverControls& controls, const InputFrame& keys) {
  InputFrame command = keys;
  if (controls.up == PedalPress::kBrakes || controls.down == PedalPress::kBrakes) {
    // Both pedals: the speed law brakes towards zero and, at rest, holds the car there.
    command.up = true;
    command.down = true;
  }
  return command;
}

double steerHeldSeconds(const DriverControls& controls, double hz) {
  return static_cast<double>(std::llabs(controls.steer_steps)) / hz;
}

double steerRampRate(const CarParams& params, double held) {
  return std::min(params.steer_rate, params.steer_ramp_start + params.steer_ramp_accel * held);
}

double steerStep(const CarParams& params, double steer, double target, double held, double dt) {
  const bool toward_centre = (steer > 0.0 && target < steer) || (steer < 0.0 && target > steer);
  if (toward_centre) {
    // Towards the centre, as fast as the wheel returns when let go; a target on the other side is
    // reached from the centre at the ramp's rate, from the next step on.
    const bool beyond = steer > 0.0 ? target < 0.0 : target > 0.0;
    return stepToward(steer, beyond ? 0.0 : target, params.steer_rate * dt);
  }
  return stepToward(steer, target, steerRampRate(params, held) * dt);
}

Gear gearOf(double speed, const DriverControls& controls) {
  if (speed > 0.0) return Gear::kDrive;
  if (speed < 0.0) return Gear::kReverse;
  const bool up = controls.up != PedalPress::kReleased;
  const bool down = controls.down != PedalPress::kReleased;
  if (controls.up == PedalPress::kDrives && !down) return Gear::kDrive;
  if (controls.down == PedalPress::kDrives && !up) return Gear::kReverse;
  return Gear::kNeutral;
}

}  // namespace cardemo
