#pragma once
/// Car parameters, state, and the fixed-step kinematic bicycle model.

#include <Eigen/Core>
#include <limits>

#include "geometry/obb2.hpp"
#include "sim/input_frame.hpp"
#include "sim/simulation_schemes.hpp"

namespace cardemo {

/// Tunable car parameters; defaults suit a 4.5 m family car.
struct CarParams {
  double length = 4.5;               ///< Body length along the heading, metres.
  double width = 1.8;                ///< Body width, metres.
  double wheelbase = 2.7;            ///< Axle distance, metres (bicycle model).
  double engine_accel = 4.0;         ///< Throttle acceleration at low speed, m/s^2.
  double brake_decel = 9.0;          ///< Braking deceleration, m/s^2.
  double reverse_accel = 2.5;        ///< Reverse acceleration, m/s^2.
  double max_reverse_speed = 8.0;    ///< Reverse is limited to this speed, m/s.
  double drag = 0.0016;              ///< Aerodynamic drag coefficient: a = drag * v * |v|, 1/m.
  double rolling_resistance = 0.15;  ///< Constant deceleration while rolling, m/s^2.
  double max_steer = 0.6;            ///< Steering lock at standstill, radians.
  double steer_rate = 2.5;  ///< Fastest wheel rate, radians of wheel angle per second: back towards
                            ///< the centre always, away from it at the end of the steering ramp.
  double steer_ramp_start = 0.4;  ///< Wheel rate away from the centre as a steering key goes down,
                                  ///< rad/s (the keyboard ramp, World::step).
  double steer_ramp_accel = 1.3;  ///< Growth of that rate per second the key stays held, rad/s^2.
  double lock_speed = 20.0;       ///< Speed (m/s) at which the lock has narrowed to half.
  double restitution = 0.2;       ///< Share of the normal speed that bounces back after an impact.
  double bounce_threshold = 1.0;  ///< Impacts slower than this (m/s) do not bounce at all.
  double skid_slip = 0.5;  ///< Lateral slip (m/s) above which the tyres count as sliding (skids).
  double grip = 9.0;  ///< Lateral acceleration the tyres can give (about 0.92 g), m/s^2: caps the
                      ///< lock at speed (v^2 tan(lock) / wheelbase <= grip) and decays the slip.
  double engine_brake = 1.5;     ///< Deceleration with no pedal held (engine braking), m/s^2.
  double handbrake_decel = 6.0;  ///< Deceleration under the handbrake, m/s^2.
  double handbrake_grip = 0.3;   ///< Share of `grip` left under the handbrake (locked rear wheels).
  double max_speed = std::numeric_limits<double>::infinity();  ///< The engine stops pushing at
                                                               ///< this forward speed, m/s.
  double contact_friction = 0.3;  ///< Coulomb coefficient of car against walls and colliders: the
                                  ///< tangential speed change is at most this times the normal one.
};

/// Kinematic state of the player's car.
struct CarState {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< Centre, world metres.
  double heading = 0.0;  ///< Radians CCW from +x, wrapped to (-pi, pi].
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< (cos, sin) of heading, kept in sync.
  double speed = 0.0;  ///< Signed speed along the heading, m/s (negative when reversing).
  double steer = 0.0;  ///< Front-wheel angle, radians, positive to the left.
  double slip = 0.0;   ///< Lateral (side-slip) speed across the heading, m/s, positive to the left.
  Eigen::Vector2d surface_normal = Eigen::Vector2d::Zero();  ///< Unit normal, from the car, of the
                                                             ///< wall or collider it rests against
                                                             ///< after the last step; 0 when free.

  /// Velocity vector in the world frame (forward speed plus lateral slip), m/s.
  [[nodiscard]] Eigen::Vector2d velocity() const {
    return {direction.x() * speed - direction.y() * slip,
            direction.y() * speed + direction.x() * slip};
  }
};

/// Steering lock at a given speed: the lock narrows as speed grows (steering geometry only).
[[nodiscard]] double steeringLock(const CarParams& params, double speed);

/// The largest wheel angle whose bicycle-model turn stays within the tyres' grip at `speed`:
/// atan(grip * wheelbase / speed^2) (pi/2 at rest).
[[nodiscard]] double gripLock(const CarParams& params, double speed);

/// The lock the wheel is steered to: the steering lock, capped by the grip lock unless the
/// handbrake is held (the rear then slides instead).
[[nodiscard]] double effectiveLock(const CarParams& params, double speed, bool handbrake);

/// Advances the car by one fixed step `dt` (seconds) under `input`: the steering angle moves first
/// (rate limited, towards effectiveLock) and is then held over the step; throttle/brake/reverse,
/// engine braking, handbrake, drag and rolling resistance drive the speed, the bicycle model the
/// heading, and the position moves along the heading, integrated by `car_step` (null: the game's
/// exact-arc RK4; lab/sim supplies the others). No scheme lets resistance or braking reverse the
/// car within a step, and none lets the engine pass `max_speed` or the reverse command pass
/// `max_reverse_speed`. Then one split step shared by every scheme (slideCar) handles the lateral
/// slip.
[[nodiscard]] CarState integrateCar(const CarState& state, const InputFrame& input,
                                    const CarParams& params, double dt,
                                    CarStepScheme car_step = nullptr);

/// The wheel angle `input` steers towards at `speed`: +-effectiveLock, or 0 when not steering.
[[nodiscard]] double steerTarget(const CarParams& params, double speed, const InputFrame& input);

/// integrateCar with the steering target given: `steer_target` must be steerTarget(params,
/// state.speed, input), computed once by a caller that needs the lock too. The wheel moves
/// towards it at `steer_rate` both ways (a key held past the keyboard ramp).
[[nodiscard]] CarState integrateCarToward(const CarState& state, const InputFrame& input,
                                          const CarParams& params, double dt, double steer_target,
                                          CarStepScheme car_step = nullptr);

/// integrateCar with the step's wheel angle given (`steer`, radians, held over the step): World
/// moves the wheel by the keyboard ramp (steerStep) and then integrates the rest here.
[[nodiscard]] CarState integrateCarSteered(const CarState& state, const InputFrame& input,
                                           const CarParams& params, double dt, double steer,
                                           CarStepScheme car_step = nullptr);

/// The lateral split step after the integrator (`steered` is the state before it): under the
/// handbrake the body turns by the integrator's yaw while the velocity keeps its direction (the
/// turn becomes slip); the position moves by the slip over dt; the slip then decays towards 0 at
/// the grip rate (handbrake_grip * grip under the handbrake), except that against a surface
/// (`surface_normal`) a decay that turns the velocity into it stops where the velocity runs along
/// it, or does not start when it already points into it (a surface square to the heading, within
/// 1e-9 rad, holds nothing: the decay cannot turn the velocity there). A state without slip and
/// without the handbrake is returned unchanged.
[[nodiscard]] CarState slideCar(CarState next, const CarState& steered, bool handbrake,
                                const CarParams& params, double dt);

/// The car's oriented box at a state.
[[nodiscard]] Obb2 carBox(const CarState& state, const CarParams& params);

}  // namespace cardemo
