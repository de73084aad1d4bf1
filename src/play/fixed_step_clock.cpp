#include "play/fixed_step_clock.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace cardemo {

FixedStepClock::FixedStepClock(double step_seconds, int max_steps_per_advance)
    : step_(step_seconds), max_steps_(max_steps_per_advance) {
  assert(step_seconds > 0.0 && max_steps_per_advance >= 1);
}

int FixedStepClock::advance(double elapsed_seconds, double speed) {
  // Fiedler, "Fix Your Timestep!": accumulate real time, consume it in whole steps, keep the rest.
  accumulator_ += std::max(0.0, elapsed_seconds) * std::max(0.0, speed);
  // Sums of decimal step sizes round a hair low; a step's billionth is close enough to whole.
  const double whole_step = step_ * (1.0 - 1e-9);
  int steps = 0;
  while (accumulator_ >= whole_step && steps < max_steps_) {
    accumulator_ -= step_;
    ++steps;
  }
  // The clamp: time we cannot catch up on is dropped (keeping the fraction for alpha), so one
  // slow frame never starts a spiral of ever longer frames.
  if (accumulator_ >= whole_step) {
    const double whole = std::floor(accumulator_ / step_ + 1e-9);
    dropped_ += whole * step_ / std::max(speed, 1e-12);
    accumulator_ -= whole * step_;
  }
  return steps;
}

double FixedStepClock::alpha() const {
  return std::clamp(accumulator_ / step_, 0.0, 0.999999);
}

}  // namespace cardemo
