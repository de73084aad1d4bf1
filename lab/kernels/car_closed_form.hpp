#pragma once
/// Closed-form solutions of the car's ODE for inputs held constant: the references that the
/// integrator tests and the run-time-against-error study (bench/tradeoff/integrators.cpp) use.

#include "sim/car.hpp"

namespace cardemo {

/// Speed (m/s) and distance travelled (m) at some time along a straight or curved run.
struct SpeedAndDistance {
  double speed = 0.0;     ///< m/s.
  double distance = 0.0;  ///< Metres along the path since the start.
};

/// Driving forward under v' = net - drag v^2 from v0 >= 0 (net = throttle minus rolling
/// resistance, m/s^2, > 0; drag in 1/m, >= 0), after t seconds: the tanh / log-cosh solution, or
/// coth / log-sinh when v0 exceeds the terminal speed sqrt(net / drag).
[[nodiscard]] SpeedAndDistance underThrottle(double v0, double net, double drag, double t);

/// Coasting forward under v' = -rolling - drag v^2 from v0 >= 0 (rolling in m/s^2, drag in 1/m,
/// both >= 0), after t seconds: the tan / log-cos solution, at rest once the car has stopped.
[[nodiscard]] SpeedAndDistance coasting(double v0, double rolling, double drag, double t);

/// The pose reached from `start` after `distance` metres along a path of constant curvature (1/m,
/// positive turning left): a circle, or a straight line when the curvature is 0. Only position,
/// heading (unwrapped, radians) and direction are set; the rest is copied from `start`.
[[nodiscard]] CarState alongArc(const CarState& start, double curvature, double distance);

}  // namespace cardemo
