#pragma once
/// A game controller's analog stick and triggers turned into the digital InputFrame, step by step,
/// so a controller game records and replays like a keyboard one.

#include "sim/input_frame.hpp"

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
  double steer = 0.0;      ///< -1 full left .. +1 full right.
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

/// Turns PadState into InputFrames, one per fixed step, with a sigma-delta per control: the share
/// of steps a key is held equals the analog level (to within one step over any stretch), so a
/// half-pressed trigger gives half the throttle on average; the handbrake button is passed on as
/// it is. The output is plain keys: the
/// recording is an ordinary replay and replays give the same hash.
class AnalogDrive {
 public:
  /// The keys for the next step.
  [[nodiscard]] InputFrame sample(const PadState& pad);
  /// Forgets the carried errors (on restart).
  void reset();

 private:
  SigmaDelta up_, down_, left_, right_;
};

/// The keys held in either frame.
[[nodiscard]] InputFrame mergeInputs(const InputFrame& a, const InputFrame& b);

}  // namespace cardemo
