#include "sim/car_schemes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/angle.hpp"
#include "geometry/trig.hpp"

namespace cardemo {
double curvatureOf(const CarState& s, const CarParams& p) {
  // Yaw rate = v tan(delta) / L (Rajamani, "Vehicle Dynamics and Control", 2nd ed., sec. 2.2), so
  // the heading changes by tan(delta) / L per metre.
  return trig::tan(s.steer) / p.wheelbase;
}

Eigen::Vector2d directionAt(const CarState& start, double heading) {
  return heading == start.heading ? start.direction : unitFromRadians(heading);
}

void setHeading(CarState& next, const CarState& start, double unwrapped) {
  next.heading = unwrapped == start.heading ? start.heading : wrapRadians(unwrapped);
  next.direction = directionAt(start, next.heading);
}

SpeedLaw speedLawFor(double speed, const InputFrame& input, const CarParams& params) {
  SpeedLaw law;
  law.drag = params.drag;
  law.rolling = params.rolling_resistance;
  law.travel = speed > 0.0 ? 1.0 : (speed < 0.0 ? -1.0 : 0.0);
  const double brake = -law.travel * params.brake_decel;  // toward zero
  if (input.handbrake) {
    law.command = -law.travel * params.handbrake_decel;
  } else if (input.up && input.down) {
    law.command = brake;
  } else if (input.up) {
    if (speed < 0.0) {
      law.command = brake;
    } else {
      law.command = params.engine_accel;
      law.travel = 1.0;
      law.limited = true;
      law.capped = true;
      law.limit = params.max_speed;
      law.cap = std::max(params.max_speed, speed);
    }
  } else if (input.down) {
    if (speed > 0.0) {
      law.command = brake;
    } else {
      law.command = -params.reverse_accel;
      law.travel = -1.0;
      law.limited = true;
      law.capped = true;
      law.limit = -params.max_reverse_speed;
      law.cap = std::min(-params.max_reverse_speed, speed);
    }
  } else {
    law.command = -law.travel * params.engine_brake;
  }
  return law;
}

double settledAtLimit(double speed, const InputFrame& input, const CarParams& params) {
  // The engine's push switches off past its limit, so the step is not continuous in a start speed
  // on the far side of it. Held against the limit, the speed lands on it or within an ulp or two
  // of it on either side (RK4's cap, a slide's turn of the velocity), and a copy of the drive
  // turned or mirrored lands on another of those values: without this, such a copy drifts by
  // about 3e-5 m in one step (tests/stress, InvarianceRandomDrives).
  constexpr double kRounding = 8.0 * std::numeric_limits<double>::epsilon();
  if (input.handbrake || input.up == input.down) return speed;
  const double limit = input.up ? params.max_speed : -params.max_reverse_speed;
  if (!std::isfinite(limit) || (input.up ? speed < 0.0 : speed > 0.0)) return speed;
  return std::abs(speed - limit) <= kRounding * std::abs(limit) ? limit : speed;
}

CarState stepArcRk4(const CarState& steered, const SpeedLaw& law, const CarParams& params,
                    double dt) {
  // RK4 on s' = v, v' = law.rate(v): the speed law does not depend on position or heading.
  const double v1 = steered.speed;
  const double a1 = law.rate(v1);
  const double v2 = law.alongTravel(v1 + 0.5 * dt * a1);
  const double a2 = law.rate(v2);
  const double v3 = law.alongTravel(v1 + 0.5 * dt * a2);
  const double a3 = law.rate(v3);
  const double v4 = law.alongTravel(v1 + dt * a3);
  const double a4 = law.rate(v4);
  const double w = dt / 6.0;
  const double distance = w * (v1 + 2.0 * v2 + 2.0 * v3 + v4);

  CarState next = steered;
  next.speed = law.endSpeed(v1 + w * (a1 + 2.0 * a2 + 2.0 * a3 + a4));
  // With the steering held the curvature is constant, so whatever the speed profile the car runs
  // along one circle (or line) and only the distance along it matters. An arc of length s turning
  // by phi has the chord s sin(phi/2) / (phi/2) along the start heading turned by phi/2 (the exact
  // update for constant curvature: Thrun, Burgard and Fox, "Probabilistic Robotics", 2005,
  // sec. 5.3.3, eq. 5.9, written in chord form so that it stays accurate as phi -> 0).
  const double turn = distance * curvatureOf(steered, params);
  setHeading(next, steered, steered.heading + turn);
  Eigen::Vector2d chord = steered.direction * distance;
  if (turn != 0.0) {
    const double half = 0.5 * turn;
    const trig::CosSin unit = trig::cosSin(half);
    const double c = unit.cos, s = unit.sin;
    const double length = distance * (s / half);
    const Eigen::Vector2d& u = steered.direction;
    chord = Eigen::Vector2d(u.x() * c - u.y() * s, u.x() * s + u.y() * c) * length;
  }
  next.position.x() = steered.position.x() + chord.x();
  next.position.y() = steered.position.y() + chord.y();
  return next;
}

}  // namespace cardemo
