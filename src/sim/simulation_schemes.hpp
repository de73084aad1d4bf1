#pragma once
/// The numerical schemes a study can swap in: one small policy, defaults are the game's.

#include "geometry/obb2.hpp"

namespace cardemo {

/// How integrateCar advances the car's ODE over one step (inputs held within the step).
/// docs/performance.md ("Run time against error") measures each against closed forms.
enum class CarIntegrator {
  kSemiImplicitEuler,  ///< Speed first, then heading and position from the new values (order 1).
  kExplicitEuler,      ///< Heading, position and speed all from the start of the step (order 1).
  kRk4,                ///< Classical Runge-Kutta over (x, y, heading, speed) (order 4).
  kArcRk4,  ///< Speed and distance by RK4; the step follows the exact arc of its constant
            ///< curvature.
};

/// How the player's motion within a step is checked against the static colliders.
enum class CollisionDetection {
  kDiscrete,    ///< One test at the end pose of each step: fast motion can pass through things.
  kSubstepped,  ///< Sub-poses at most half the car's smaller extent apart.
  kContinuous,  ///< Swept SAT to the first time of impact when the step moves fast (default).
};

/// Which box of the player feeds the broad phase.
enum class BroadPhaseBox {
  kTight,          ///< Tight AABB of the current OBB (default).
  kRotationProof,  ///< The seed demo's box around the circumscribed circle.
};

/// The alternatives studies compare (docs/performance.md); the game runs the defaults.
struct SimulationSchemes {
  CollisionDetection collision = CollisionDetection::kContinuous;  ///< Fast-motion scheme.
  BroadPhaseBox broad_phase_box = BroadPhaseBox::kTight;           ///< Player box for queries.
  /// After a push-out (a pure translation), skip the narrow test of a candidate whose separation
  /// before the push exceeds the distance pushed plus a rounding margin: it stays separated, so
  /// the contacts are the same with or without (false runs every test: the twin tests compare).
  bool translation_bound = true;
};

/// The broad-phase query box of the player's box `box`, whose tight bounds are `tight`.
[[nodiscard]] inline Aabb2 queryBox(const Obb2& box, const Aabb2& tight, BroadPhaseBox kind) {
  return kind == BroadPhaseBox::kTight ? tight : box.rotationProofAabb();
}

}  // namespace cardemo
