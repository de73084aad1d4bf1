#pragma once
// Runs of the car with inputs held and a closed-form answer, shared by the integrator tests.

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "lab/kernels/car_closed_form.hpp"
#include "sim/car.hpp"

namespace cardemo::test {

// One held-input run: start, keys, parameters and the exact pose at time t.
struct ClosedFormRun {
  std::string name;
  CarParams params;
  CarState start;
  InputFrame input;
  std::function<CarState(double)> exact;  // pose at t seconds
};

// Position error of a run integrated at `hz` for `seconds` (whole steps).
struct RunError {
  double final_error = 0.0;  // metres, at the last step
  double max_error = 0.0;    // metres, over every step
};

inline RunError integrate(const ClosedFormRun& run, CarStepScheme integrator, int hz,
                          double seconds) {
  const CarParams& p = run.params;
  CarState s = run.start;
  const long steps = std::lround(seconds * hz);
  const double dt = 1.0 / hz;
  RunError e;
  for (long n = 1; n <= steps; ++n) {
    s = integrateCar(s, run.input, p, dt, integrator);
    const double err = (s.position - run.exact(static_cast<double>(n) / hz).position).norm();
    e.max_error = std::max(e.max_error, err);
    e.final_error = err;
  }
  return e;
}

// Strong drag (terminal speed 8.8 m/s) so that the speed law is far from linear within 2 s.
inline CarParams draggy() {
  CarParams p;
  p.drag = 0.05;
  p.rolling_resistance = 0.15;
  return p;
}

inline ClosedFormRun throttleRun() {
  ClosedFormRun r{"throttle", draggy(), {}, {true, false, false, false}, {}};
  r.start.speed = 2.0;
  const CarParams p = r.params;
  const CarState s0 = r.start;
  r.exact = [p, s0](double t) {
    const SpeedAndDistance sd =
        underThrottle(s0.speed, p.engine_accel - p.rolling_resistance, p.drag, t);
    CarState s = alongArc(s0, 0.0, sd.distance);
    s.speed = sd.speed;
    return s;
  };
  return r;
}

inline ClosedFormRun coastRun() {
  ClosedFormRun r{"coast", draggy(), {}, {}, {}};
  r.start.speed = 10.0;
  r.start.heading = 2.0;
  r.start.direction = {std::cos(2.0), std::sin(2.0)};
  const CarParams p = r.params;
  const CarState s0 = r.start;
  r.exact = [p, s0](double t) {
    const SpeedAndDistance sd =
        coasting(s0.speed, p.rolling_resistance + p.engine_brake, p.drag, t);
    CarState s = alongArc(s0, 0.0, sd.distance);
    s.speed = sd.speed;
    return s;
  };
  return r;
}

// Constant speed (no drag, no rolling resistance) with the wheel held at the lock for that speed.
inline ClosedFormRun circleRun() {
  ClosedFormRun r{"circle", {}, {}, {false, false, true, false}, {}};
  r.params.drag = 0.0;
  r.params.rolling_resistance = 0.0;
  r.params.engine_brake = 0.0;
  r.start.position = {3.0, -2.0};
  r.start.heading = 0.7;
  r.start.direction = {std::cos(0.7), std::sin(0.7)};
  r.start.speed = 10.0;
  r.start.steer = effectiveLock(r.params, r.start.speed, false);
  const CarParams p = r.params;
  const CarState s0 = r.start;
  r.exact = [p, s0](double t) {
    return alongArc(s0, std::tan(s0.steer) / p.wheelbase, s0.speed * t);
  };
  return r;
}

// Throttle with the wheel held: the path is still one circle, the distance the log-cosh law.
inline ClosedFormRun acceleratingTurnRun() {
  ClosedFormRun r{"accelerating_turn", draggy(), {}, {true, false, true, false}, {}};
  r.params.lock_speed = 0.0;  // no narrowing: the lock, and so the curvature, stay constant
  r.params.max_steer = 0.3;
  r.start.speed = 2.0;
  r.start.steer = r.params.max_steer;
  const CarParams p = r.params;
  const CarState s0 = r.start;
  r.exact = [p, s0](double t) {
    const SpeedAndDistance sd =
        underThrottle(s0.speed, p.engine_accel - p.rolling_resistance, p.drag, t);
    CarState s = alongArc(s0, std::tan(s0.steer) / p.wheelbase, sd.distance);
    s.speed = sd.speed;
    return s;
  };
  return r;
}

}  // namespace cardemo::test
