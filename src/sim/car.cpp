#include "sim/car.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angle.hpp"
#include "sim/car_schemes.hpp"

namespace cardemo {
namespace {

// Moves `value` toward `target` by at most `max_delta`, landing exactly on the target.
double approach(double value, double target, double max_delta) {
  if (value < target) return std::min(value + max_delta, target);
  if (value > target) return std::max(value - max_delta, target);
  return value;
}

// Speed after the driver's command (throttle, brake, reverse) over one step.
double commandedSpeed(double v, const InputFrame& in, const CarParams& p, double dt) {
  const double brake = p.brake_decel * dt;
  if (in.up && in.down) return approach(v, 0.0, brake);
  if (in.up) return v < 0.0 ? approach(v, 0.0, brake) : v + p.engine_accel * dt;
  if (in.down) {
    if (v > 0.0) return approach(v, 0.0, brake);
    // Already beyond the reverse limit (an initial speed from the scene): leave it to drag.
    if (v <= -p.max_reverse_speed) return v;
    return std::max(v - p.reverse_accel * dt, -p.max_reverse_speed);
  }
  return v;
}

// Speed after drag (a = -drag v |v|) and rolling resistance; resistance stops the car, it never
// reverses it.
double resistedSpeed(double v, const CarParams& p, double dt) {
  if (v == 0.0) return v;
  const double magnitude = std::abs(v);
  const double loss = (p.drag * magnitude * magnitude + p.rolling_resistance) * dt;
  if (loss >= magnitude) return 0.0;
  return v > 0.0 ? v - loss : v + loss;
}

// The product's original update, kept bit for bit: command, then resistance (operator splitting),
// then the new speed drives this step's rotation and translation.
CarState stepSemiImplicitEuler(const CarState& steered, const InputFrame& input,
                               const CarParams& params, double dt) {
  CarState next = steered;
  next.speed = resistedSpeed(commandedSpeed(steered.speed, input, params, dt), params, dt);

  // Kinematic bicycle model, reference point moving along the heading (no slip):
  // yaw rate = v tan(delta) / L (Rajamani, "Vehicle Dynamics and Control", 2nd ed., sec. 2.2).
  const double yaw_rate = next.speed * std::tan(next.steer) / params.wheelbase;
  next.heading = wrapRadians(steered.heading + yaw_rate * dt);
  // Recomputed from the angle only when it changed: an exact axis-aligned start direction from
  // unitFromDegrees survives straight driving, and the direction can never drift off unit length.
  if (next.heading != steered.heading) next.direction = unitFromRadians(next.heading);

  const double distance = next.speed * dt;
  next.position.x() = steered.position.x() + next.direction.x() * distance;
  next.position.y() = steered.position.y() + next.direction.y() * distance;
  return next;
}

}  // namespace

double steeringLock(const CarParams& params, double speed) {
  if (!(params.lock_speed > 0.0)) return params.max_steer;
  const double r = speed / params.lock_speed;
  return params.max_steer / (1.0 + r * r);
}

CarState integrateCar(const CarState& state, const InputFrame& input, const CarParams& params,
                      double dt) {
  CarState steered = state;
  const double lock = steeringLock(params, state.speed);
  double target = 0.0;
  if (input.left && !input.right) target = lock;
  if (input.right && !input.left) target = -lock;
  steered.steer = approach(state.steer, target, params.steer_rate * dt);

  switch (params.integrator) {
    case CarIntegrator::kExplicitEuler:
      return stepExplicitEuler(steered, speedLawFor(state.speed, input, params), params, dt);
    case CarIntegrator::kRk4:
      return stepRk4(steered, speedLawFor(state.speed, input, params), params, dt);
    case CarIntegrator::kArcRk4:
      return stepArcRk4(steered, speedLawFor(state.speed, input, params), params, dt);
    case CarIntegrator::kSemiImplicitEuler:
      break;
  }
  return stepSemiImplicitEuler(steered, input, params, dt);
}

Obb2 carBox(const CarState& state, const CarParams& params) {
  return {state.position, state.direction, {0.5 * params.length, 0.5 * params.width}};
}

}  // namespace cardemo
