#pragma once
/// The one policy through which studies swap in other schemes than the game's (lab/sim supplies
/// them): a hook left null is the game's own scheme, at the cost of one well-predicted branch.

#include "geometry/aabb.hpp"
#include "geometry/obb2.hpp"

namespace cardemo {

struct CarParams;
struct CarState;
struct SpeedLaw;
class StepMotion;

/// Advances the car over one step of `dt` seconds from `steered` (the start state with the step's
/// steering angle set) under the speed law `law`, in place of the game's exact-arc RK4
/// (stepArcRk4).
using CarStepScheme = CarState (*)(const CarState& steered, const SpeedLaw& law,
                                   const CarParams& params, double dt);

/// Moves the player from `start` to `next` within a step through `motion`, testing for contact on
/// the way, in place of the game's continuous scheme (StepMotion::continuous). Returns the
/// fraction of the step at which contact was found (1: at the end pose, or none).
using MotionScheme = double (*)(StepMotion& motion, const CarState& start, const CarState& next);

/// The broad-phase query box of the player's box, in place of its tight bounds.
using QueryBoxScheme = Aabb2 (*)(const Obb2& box);

/// The alternatives studies compare (docs/performance.md); all null, the game's.
struct SimulationSchemes {
  CarStepScheme car_step = nullptr;    ///< The car's integrator; null: exact-arc RK4.
  MotionScheme motion = nullptr;       ///< Fast-motion collision scheme; null: continuous.
  QueryBoxScheme query_box = nullptr;  ///< Player box for broad-phase queries; null: tight AABB.
  /// After a push-out (a pure translation), skip the narrow test of a candidate whose separation
  /// before the push exceeds the distance pushed plus a rounding margin: it stays separated, so
  /// the contacts are the same with or without (false runs every test: the twin tests compare).
  bool translation_bound = true;
};

/// The broad-phase query box of the player's box `box`, whose tight bounds are `tight`.
[[nodiscard]] inline Aabb2 queryBox(const Obb2& box, const Aabb2& tight,
                                    const SimulationSchemes& schemes) {
  return schemes.query_box == nullptr ? tight : schemes.query_box(box);
}

}  // namespace cardemo
