#pragma once
/// The car integrators that studies compare with the game's exact-arc RK4 (src/sim/car_schemes),
/// on its speed law: each is a CarStepScheme for SimulationSchemes::car_step or integrateCar.

#include "sim/car.hpp"
#include "sim/car_schemes.hpp"

namespace cardemo {

/// Semi-implicit Euler (the product's original update, kept bit for bit): the command, then drag
/// and rolling resistance, give the new speed, which then drives the heading and the position.
[[nodiscard]] CarState stepSemiImplicitEuler(const CarState& steered, const SpeedLaw& law,
                                             const CarParams& params, double dt);

/// Explicit Euler: heading, position and speed all advance with the derivatives at the start of
/// the step. `steered` is the state at the start with the step's steering angle already set.
[[nodiscard]] CarState stepExplicitEuler(const CarState& steered, const SpeedLaw& law,
                                         const CarParams& params, double dt);

/// Classical fourth-order Runge-Kutta over (x, y, heading, speed) with the steering held.
[[nodiscard]] CarState stepRk4(const CarState& steered, const SpeedLaw& law,
                               const CarParams& params, double dt);

}  // namespace cardemo
