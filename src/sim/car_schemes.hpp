#pragma once
/// The car's integrator: the speed law of one step (the driver's mode, chosen once) and the
/// exact-arc update built on it, the game's (lab/sim/car_integrators builds the alternatives that
/// studies compare on the same law).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "sim/car.hpp"
#include "sim/input_frame.hpp"

namespace cardemo {

/// The speed ODE of one step with the inputs held: v' = command - drag v|v| - rolling * travel.
/// The mode (handbrake, throttle, brake, reverse, coast under engine braking) is chosen once from
/// the speed at the start of the step, as the semi-implicit update does; within the step the car
/// stops at zero instead of reversing, and the engine (forward, or the reverse command) switches
/// off at its limit (max_speed, or -max_reverse_speed).
struct SpeedLaw {
  double command = 0.0;  ///< Driver's acceleration (throttle, brake, reverse, engine braking),
                         ///< m/s^2, signed.
  double travel = 0.0;   ///< Direction of travel over the step: +1, -1, or 0 (at rest and stays).
  double drag = 0.0;     ///< Drag coefficient, 1/m.
  double rolling = 0.0;  ///< Rolling resistance, m/s^2.
  double limit = 0.0;    ///< Speed (m/s, signed like `travel`) beyond which the command is off.
  bool limited = false;  ///< True when `command` is the engine's, which switches off past `limit`.
  bool capped = false;   ///< True when the step's end speed is clamped to `cap`.
  /// The end speed's bound when capped (m/s, signed like `travel`): `limit`, or the start speed
  /// when that is already past it (a slide or the scene's initial speed).
  double cap = 0.0;

  // rate, alongTravel and endSpeed are defined here (inline) because RK4 calls them 4 times a step.

  /// Acceleration at speed `v` (m/s^2); zero once the car has stopped against its travel.
  [[nodiscard]] double rate(double v) const {
    if (travel == 0.0) return 0.0;
    // Off only past the limit: a car exactly at it (where the cap puts it) pushes as one an ulp
    // below does, so that the step is continuous in the start speed there.
    const double push = limited && travel * v > travel * limit ? 0.0 : command;
    const double a = push - drag * v * std::abs(v) - rolling * travel;
    // Stopped (or at rest and about to move): nothing here can push the car against its travel.
    if (travel * v <= 0.0 && travel * a <= 0.0) return 0.0;
    return a;
  }
  /// `v` clamped so that it never points against the direction of travel (m/s).
  [[nodiscard]] double alongTravel(double v) const {
    if (travel > 0.0) return std::max(v, 0.0);
    if (travel < 0.0) return std::min(v, 0.0);
    return 0.0;
  }
  /// The speed at the end of a step: along the travel and within the cap (m/s).
  [[nodiscard]] double endSpeed(double v) const {
    const double along = alongTravel(v);
    if (!capped) return along;
    return travel > 0.0 ? std::min(along, cap) : std::max(along, cap);
  }
};

/// The speed law of one step from the speed at its start (m/s) and the keys held.
[[nodiscard]] SpeedLaw speedLawFor(double speed, const InputFrame& input, const CarParams& params);

/// The start speed (m/s) of a step, with a speed within rounding of the limit that the held
/// throttle or reverse key drives towards (max_speed, -max_reverse_speed) taken as that limit.
[[nodiscard]] double settledAtLimit(double speed, const InputFrame& input, const CarParams& params);

/// Bicycle-model curvature of the path at `state`'s steering angle, 1/m: tan(steer) / wheelbase.
[[nodiscard]] double curvatureOf(const CarState& state, const CarParams& params);

/// The unit vector of `heading` (radians); `start`'s stored direction when the angle has not moved,
/// so that an exact axis-aligned direction from unitFromDegrees survives straight driving.
[[nodiscard]] Eigen::Vector2d directionAt(const CarState& start, double heading);

/// Sets `next`'s heading to `unwrapped` wrapped, and its direction, recomputed only when the angle
/// changed from `start`'s.
void setHeading(CarState& next, const CarState& start, double unwrapped);

/// Speed and distance travelled by RK4 over (distance, speed); the position then follows the exact
/// circular arc of the step's constant curvature tan(steer) / wheelbase over that distance.
[[nodiscard]] CarState stepArcRk4(const CarState& steered, const SpeedLaw& law,
                                  const CarParams& params, double dt);

}  // namespace cardemo
