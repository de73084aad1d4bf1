#include "lab/sim/car_integrators.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"
#include "geometry/trig.hpp"

namespace cardemo {
namespace {

// Speed after drag (a = -drag v |v|) and rolling resistance; resistance stops the car, it never
// reverses it.
double resistedSpeed(double v, const CarParams& p, double dt) {
  if (v == 0.0) return v;
  const double magnitude = std::abs(v);
  const double loss = (p.drag * magnitude * magnitude + p.rolling_resistance) * dt;
  if (loss >= magnitude) return 0.0;
  return v > 0.0 ? v - loss : v + loss;
}

// The command alone as one explicit step from `v` over `dt` (semi-implicit Euler's first half):
// clamped at the cap when capped, else toward zero, stopping exactly on it.
double commandedSpeed(const SpeedLaw& law, double v, double dt) {
  if (law.capped) {
    const double pushed = v + law.command * dt;
    return law.travel > 0.0 ? std::min(pushed, law.cap) : std::max(pushed, law.cap);
  }
  // Braking, engine braking or the handbrake: toward zero, landing on it exactly.
  const double max_delta = std::abs(law.command) * dt;
  if (v < 0.0) return std::min(v + max_delta, 0.0);
  if (v > 0.0) return std::max(v - max_delta, 0.0);
  return v;
}

}  // namespace

CarState stepSemiImplicitEuler(const CarState& steered, const SpeedLaw& law,
                               const CarParams& params, double dt) {
  // The product's original update, kept bit for bit: command, then resistance (operator
  // splitting), then the new speed drives this step's rotation and translation.
  CarState next = steered;
  next.speed = resistedSpeed(commandedSpeed(law, steered.speed, dt), params, dt);

  // Kinematic bicycle model, reference point moving along the heading (no slip):
  // yaw rate = v tan(delta) / L (Rajamani, "Vehicle Dynamics and Control", 2nd ed., sec. 2.2).
  const double yaw_rate = next.speed * trig::tan(next.steer) / params.wheelbase;
  next.heading = wrapRadians(steered.heading + yaw_rate * dt);
  // Recomputed from the angle only when it changed: an exact axis-aligned start direction from
  // unitFromDegrees survives straight driving, and the direction can never drift off unit length.
  if (next.heading != steered.heading) next.direction = unitFromRadians(next.heading);

  const double distance = next.speed * dt;
  next.position.x() = steered.position.x() + next.direction.x() * distance;
  next.position.y() = steered.position.y() + next.direction.y() * distance;
  return next;
}

CarState stepExplicitEuler(const CarState& steered, const SpeedLaw& law, const CarParams& params,
                           double dt) {
  CarState next = steered;
  const double v = steered.speed;
  next.speed = law.endSpeed(v + law.rate(v) * dt);
  setHeading(next, steered, steered.heading + v * curvatureOf(steered, params) * dt);
  const double distance = v * dt;
  next.position.x() = steered.position.x() + steered.direction.x() * distance;
  next.position.y() = steered.position.y() + steered.direction.y() * distance;
  return next;
}

CarState stepRk4(const CarState& steered, const SpeedLaw& law, const CarParams& params, double dt) {
  // Classical RK4 (Hairer, Norsett and Wanner, "Solving Ordinary Differential Equations I",
  // sec. II.1, table 1.2) on x' = v cos(h), y' = v sin(h), h' = v k, v' = law.rate(v). Stage speeds
  // are kept along the travel so that a stage never drives the car backwards through a stop.
  const double k = curvatureOf(steered, params);
  const double h0 = steered.heading, v1 = steered.speed;
  const Eigen::Vector2d d1 = steered.direction;
  const double a1 = law.rate(v1);

  const double v2 = law.alongTravel(v1 + 0.5 * dt * a1);
  const double h2 = h0 + 0.5 * dt * (v1 * k);
  const Eigen::Vector2d d2 = directionAt(steered, h2);
  const double a2 = law.rate(v2);

  const double v3 = law.alongTravel(v1 + 0.5 * dt * a2);
  const double h3 = h0 + 0.5 * dt * (v2 * k);
  const Eigen::Vector2d d3 = directionAt(steered, h3);
  const double a3 = law.rate(v3);

  const double v4 = law.alongTravel(v1 + dt * a3);
  const double h4 = h0 + dt * (v3 * k);
  const Eigen::Vector2d d4 = directionAt(steered, h4);
  const double a4 = law.rate(v4);

  const double w = dt / 6.0;
  CarState next = steered;
  next.speed = law.endSpeed(v1 + w * (a1 + 2.0 * a2 + 2.0 * a3 + a4));
  setHeading(next, steered, h0 + w * ((v1 + 2.0 * v2 + 2.0 * v3 + v4) * k));
  next.position.x() = steered.position.x() +
                      w * (v1 * d1.x() + 2.0 * v2 * d2.x() + 2.0 * v3 * d3.x() + v4 * d4.x());
  next.position.y() = steered.position.y() +
                      w * (v1 * d1.y() + 2.0 * v2 * d2.y() + 2.0 * v3 * d3.y() + v4 * d4.y());
  return next;
}

}  // namespace cardemo
