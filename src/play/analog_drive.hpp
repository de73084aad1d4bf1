#pragma once
/// A game controller's analog stick and triggers turned into the digital InputFrame, step by step,
/// so a controller game records and replays like a keyboard one.

#include <cstdint>

#include "sim/input_frame.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// First-order sigma-delta modulator: a level in [0, 1] in, one on/off per step out, such that
/// over any run of steps the number of "on" steps differs from the sum of the levels by at most
/// 1/2. A level held at 0.3 gives throttle on 3 steps in 10, evenly spread.
class SigmaDelta {
 public:
  /// The next step's output for `level` (clamped to [0, 1]; NaN counts as 0).
  [[nodiscard]] bool next(double level);
  /// Forgets the carried error (a restarted game starts from the same state).
  void reset() { error_ = 0.0; }

 private:
  double error_ = 0.0;  // sum of levels minus "on" steps so far, in [-1/2, 1/2)
};

/// A controller's driving controls, normalised.
struct PadState {
  double steer = 0.0;      ///< -1 full left .. +1 full right (that share of the steering lock).
  double throttle = 0.0;   ///< 0 .. 1.
  double brake = 0.0;      ///< 0 .. 1 (brake, then reverse, as the Down key).
  bool handbrake = false;  ///< The handbrake button.
};

/// An SDL axis value (-32768 .. 32767) as -1 .. 1, with `dead_zone` (a share of full travel) read
/// as 0 and the rest rescaled so the response starts at 0 just outside it and reaches 1 at the end.
[[nodiscard]] double axisLevel(int raw, double dead_zone = 0.15);

/// The controller layout: left stick x steers; the right trigger, or the left stick pushed up,
/// is throttle; the left trigger, or the stick pulled down, is brake (the larger of the two wins).
/// Raw SDL values: stick axes -32768 .. 32767 (y grows downwards), triggers 0 .. 32767.
[[nodiscard]] PadState padFromAxes(int left_x, int left_y, int trigger_left, int trigger_right,
                                   bool handbrake);

/// Turns PadState into InputFrames, one per fixed step. The throttle and the brake are each a
/// sigma-delta: the share of steps the key is held equals the analog level (to within one step
/// over any stretch), so a half-pressed trigger gives half the throttle on average. A squeeze
/// that began while the car moved against its pedal (the brake while moving forward, the throttle
/// while moving backward) only brakes: once the car stands it holds no key, so the simulation
/// sees no press that begins at a standstill, and it drives the other way only after the trigger
/// is let go and squeezed again (the keyboard's rule, docs/controls.md). Steering is a servo on
/// the wheel angle: each step holds Left, Right or neither, whichever brings the wheel the World
/// would steer nearest to the stick's share of the steering lock (World::steerAfter), so the wheel
/// follows the stick in proportion whatever the keyboard ramp. The handbrake button is passed on
/// as it is. The output is plain keys: the recording is an ordinary replay and replays give the
/// same hash.
class AnalogDrive {
 public:
  /// The keys for the next step of `world`.
  [[nodiscard]] InputFrame sample(const PadState& pad, const World& world);
  /// Forgets the carried errors and squeezes (on restart).
  void reset();

 private:
  // A trigger's squeeze in progress: none (at rest), one that drives, one that only brakes.
  enum class Squeeze : std::uint8_t { kNone, kDrives, kBrakes };
  // The pedal key of a step for `level`, `against` when the car moves against the pedal.
  static bool pedal(SigmaDelta& modulator, Squeeze& squeeze, double level, bool against);

  SigmaDelta up_, down_;
  Squeeze up_squeeze_ = Squeeze::kNone;
  Squeeze down_squeeze_ = Squeeze::kNone;
};

/// The keys held in either frame.
[[nodiscard]] InputFrame mergeInputs(const InputFrame& a, const InputFrame& b);

}  // namespace cardemo
