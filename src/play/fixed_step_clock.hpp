#pragma once
/// The accumulator of a fixed-step loop (Fiedler, "Fix Your Timestep!"): real time in, whole
/// steps out, with a clamp on catch-up steps and the blend factor for interpolated drawing.

namespace cardemo {

/// Turns elapsed wall-clock seconds into a number of fixed steps. Pure arithmetic: the caller
/// measures time; the simulation never sees a clock.
class FixedStepClock {
 public:
  /// `step_seconds` per step; at most `max_steps_per_advance` steps per advance() (a slow frame
  /// drops time instead of spiralling).
  FixedStepClock(double step_seconds, int max_steps_per_advance);
  /// Adds `elapsed_seconds` (scaled by `speed`, e.g. 0.25..8 for playback) and returns how many
  /// steps to run now (0..max_steps_per_advance).
  int advance(double elapsed_seconds, double speed = 1.0);
  /// Fraction of a step accumulated but not yet run, in [0, 1): the blend between the last two
  /// states for drawing.
  [[nodiscard]] double alpha() const;
  /// Seconds of wall-clock time dropped by the clamp so far.
  [[nodiscard]] double droppedSeconds() const { return dropped_; }

 private:
  double step_;
  int max_steps_;
  double accumulator_ = 0.0;
  double dropped_ = 0.0;
};

}  // namespace cardemo
