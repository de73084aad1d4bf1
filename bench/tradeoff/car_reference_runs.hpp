#pragma once
// The integrator study's runs: game parameters, inputs held, and a closed-form answer for each
// (src/kernels/car_closed_form.hpp). The tests in tests/sim use harsher parameters to expose
// orders; these are what a player does.

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lab/kernels/car_closed_form.hpp"
#include "sim/car.hpp"

namespace cardemo::tradeoff {

/// One held-input run with its exact solution.
struct ReferenceRun {
  std::string name;      ///< CSV `case` column.
  CarParams params;      ///< Game defaults unless the closed form needs a change.
  CarState start;        ///< Pose, speed and steering at t = 0.
  InputFrame input;      ///< Keys held for the whole run.
  double curvature = 0;  ///< Of the exact path, 1/m (0 for a straight line).
  /// Speed and distance along the path at t seconds.
  SpeedAndDistance (*law)(const ReferenceRun&, double) = nullptr;

  /// The exact pose at t seconds.
  [[nodiscard]] CarState exact(double t) const {
    const SpeedAndDistance sd = law(*this, t);
    CarState s = alongArc(start, curvature, sd.distance);
    s.speed = sd.speed;
    return s;
  }
};

inline SpeedAndDistance throttleLaw(const ReferenceRun& r, double t) {
  const CarParams& p = r.params;
  return underThrottle(r.start.speed, p.engine_accel - p.rolling_resistance, p.drag, t);
}

inline SpeedAndDistance coastLaw(const ReferenceRun& r, double t) {
  // With no pedal held, engine braking is one more constant deceleration beside rolling resistance.
  const CarParams& p = r.params;
  return coasting(r.start.speed, p.rolling_resistance + p.engine_brake, p.drag, t);
}

inline SpeedAndDistance cruiseLaw(const ReferenceRun& r, double t) {
  return {r.start.speed, r.start.speed * t};
}

/// The four runs: full throttle from rest; coasting from 30 m/s (rolling resistance, engine braking
/// and drag); a 15 m/s circle at the lock for that speed, which the grip limit sets (drag, rolling
/// resistance and engine braking off so the speed holds); full throttle from 5 m/s with the wheel
/// held at 0.1 rad (the lock's narrowing and the grip limit off so the curvature holds).
inline std::vector<ReferenceRun> referenceRuns() {
  std::vector<ReferenceRun> runs;
  const double heading = 0.3;  // off-axis, so both coordinates carry error
  CarState start;
  start.heading = heading;
  start.direction = {std::cos(heading), std::sin(heading)};

  ReferenceRun throttle{"throttle", {}, start, {true, false, false, false}, 0.0, throttleLaw};
  runs.push_back(throttle);

  ReferenceRun coast{"coast", {}, start, {}, 0.0, coastLaw};
  coast.start.speed = 30.0;
  runs.push_back(coast);

  ReferenceRun circle{"circle", {}, start, {false, false, true, false}, 0.0, cruiseLaw};
  circle.params.drag = 0.0;
  circle.params.rolling_resistance = 0.0;
  circle.params.engine_brake = 0.0;
  circle.start.speed = 15.0;
  circle.start.steer = effectiveLock(circle.params, circle.start.speed, false);
  circle.curvature = std::tan(circle.start.steer) / circle.params.wheelbase;
  runs.push_back(circle);

  ReferenceRun turn{"accelerating_turn", {}, start, {true, false, true, false}, 0.0, throttleLaw};
  turn.params.lock_speed = 0.0;
  turn.params.grip = std::numeric_limits<double>::infinity();
  turn.params.max_steer = 0.1;
  turn.start.speed = 5.0;
  turn.start.steer = turn.params.max_steer;
  turn.curvature = std::tan(turn.start.steer) / turn.params.wheelbase;
  runs.push_back(turn);
  return runs;
}

}  // namespace cardemo::tradeoff
