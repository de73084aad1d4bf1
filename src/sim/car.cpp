#include "sim/car.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/angle.hpp"
#include "geometry/trig.hpp"
#include "sim/car_schemes.hpp"

namespace cardemo {
namespace {

// |sin| of the angle between the heading and a surface's tangent below which the surface counts as
// square to the heading (slideCar): far above the ulps of two unit vectors, far below any angle a
// car meets a surface at on purpose (1e-9 rad).
constexpr double kSquareToHeading = 1e-9;

// Moves `value` toward `target` by at most `max_delta`, landing exactly on the target.
double approach(double value, double target, double max_delta) {
  if (value < target) return std::min(value + max_delta, target);
  if (value > target) return std::max(value - max_delta, target);
  return value;
}

}  // namespace

double steeringLock(const CarParams& params, double speed) {
  if (!(params.lock_speed > 0.0)) return params.max_steer;
  const double r = speed / params.lock_speed;
  return params.max_steer / (1.0 + r * r);
}

double gripLock(const CarParams& params, double speed) {
  // Steady turning on the bicycle model: lateral acceleration v^2 tan(delta) / L (Rajamani,
  // "Vehicle Dynamics and Control", 2nd ed., sec. 2.2); capping it at the grip gives the lock.
  const double v2 = speed * speed;
  if (!(v2 > 0.0)) return 0.5 * std::numbers::pi;
  return trig::atan(params.grip * params.wheelbase / v2);
}

double effectiveLock(const CarParams& params, double speed, bool handbrake) {
  const double lock = steeringLock(params, speed);
  return handbrake ? lock : std::min(lock, gripLock(params, speed));
}

CarState slideCar(CarState next, const CarState& steered, bool handbrake, const CarParams& params,
                  double dt) {
  double grip = params.grip;
  if (handbrake) {
    grip *= params.handbrake_grip;
    // The rear tyres slide: the body turns by the integrator's yaw but the velocity keeps its
    // direction, so the turn shows up, seen from the body, as slip; only the slip's decay below
    // (at the rear's reduced grip) then pulls the velocity round.
    const double turn = wrapRadians(next.heading - steered.heading);
    if (turn != 0.0) {
      const trig::CosSin unit = trig::cosSin(turn);
      const double c = unit.cos, s = unit.sin;
      const double forward = next.speed * c + next.slip * s;
      next.slip = next.slip * c - next.speed * s;
      next.speed = forward;
    }
  }
  if (next.slip == 0.0) return next;
  const double lateral = next.slip * dt;
  next.position.x() -= next.direction.y() * lateral;
  next.position.y() += next.direction.x() * lateral;
  double slip = approach(next.slip, 0.0, grip * dt);
  // Against a surface the tyres cannot pull the car into what holds it: a decay that would turn
  // the velocity into the surface goes at most as far as the slip whose velocity runs along it, and
  // not at all once the velocity already points into it. Otherwise a car pushed along a wall at an
  // angle sticks (each frame's decay is taken back by the response, less friction), and one
  // braking along it drifts off and re-touches it.
  const Eigen::Vector2d& n = next.surface_normal;
  const double lateral_n = next.direction.x() * n.y() - next.direction.y() * n.x();
  const double change = slip - next.slip;
  // A surface square to the heading (the car's own face against it, whose normal is the car's
  // axis to a few ulps) leaves the normal velocity to the speed alone: the decay cannot turn it,
  // and the sign of lateral_n there is rounding, which a rotated scene rounds the other way.
  if (std::abs(lateral_n) > kSquareToHeading && change * lateral_n > 0.0) {
    const double forward_n = next.direction.x() * n.x() + next.direction.y() * n.y();
    const double along = -next.speed * forward_n / lateral_n;
    const double to_along = along - next.slip;
    if (!(to_along * change > 0.0)) {
      slip = next.slip;
    } else if (std::abs(to_along) < std::abs(change)) {
      slip = along;
    }
  }
  next.slip = slip;
  return next;
}

double steerTarget(const CarParams& params, double speed, const InputFrame& input) {
  if (input.left == input.right) return 0.0;  // the lock (an atan at speed) only when steering
  const double lock = effectiveLock(params, speed, input.handbrake);
  return input.left ? lock : -lock;
}

CarState integrateCar(const CarState& state, const InputFrame& input, const CarParams& params,
                      double dt, CarStepScheme car_step) {
  return integrateCarToward(state, input, params, dt, steerTarget(params, state.speed, input),
                            car_step);
}

CarState integrateCarToward(const CarState& state, const InputFrame& input, const CarParams& params,
                            double dt, double steer_target, CarStepScheme car_step) {
  return integrateCarSteered(state, input, params, dt,
                             approach(state.steer, steer_target, params.steer_rate * dt), car_step);
}

CarState integrateCarSteered(const CarState& state, const InputFrame& input,
                             const CarParams& params, double dt, double steer,
                             CarStepScheme car_step) {
  CarState steered = state;
  steered.steer = steer;
  steered.speed = settledAtLimit(state.speed, input, params);

  const SpeedLaw law = speedLawFor(steered.speed, input, params);
  const CarState next = car_step == nullptr ? stepArcRk4(steered, law, params, dt)
                                            : car_step(steered, law, params, dt);
  // Lie splitting (Hairer, Lubich and Wanner, "Geometric Numerical Integration", 2nd ed., sec.
  // II.5): the longitudinal schemes above keep their closed forms; the slip is one shared step.
  if (next.slip == 0.0 && !input.handbrake) return next;
  return slideCar(next, steered, input.handbrake, params, dt);
}

Obb2 carBox(const CarState& state, const CarParams& params) {
  return {state.position, state.direction, {0.5 * params.length, 0.5 * params.width}};
}

}  // namespace cardemo
