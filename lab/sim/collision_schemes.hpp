#pragma once
/// The collision schemes that studies compare with the game's continuous one (src/sim/world): each
/// is a MotionScheme for SimulationSchemes::motion, and rotationProofBox a QueryBoxScheme.

#include "geometry/aabb.hpp"
#include "geometry/obb2.hpp"
#include "sim/world.hpp"

namespace cardemo {

/// One contact test, at the end pose of the step: fast motion can pass through things.
double moveDiscrete(StepMotion& motion, const CarState& start, const CarState& next);

/// Sub-poses at most half the car's smaller extent apart (positions and heading interpolated), the
/// first that touches anything ending the step there: nothing that thick can be passed through.
double moveSubstepped(StepMotion& motion, const CarState& start, const CarState& next);

/// The seed demo's broad-phase box: the square around the box's circumscribed circle, which holds
/// the box at any heading.
[[nodiscard]] Aabb2 rotationProofBox(const Obb2& box);

}  // namespace cardemo
