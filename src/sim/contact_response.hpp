#pragma once
/// Velocity and position response of the player's car against static surfaces.

#include <Eigen/Core>

#include "geometry/aabb.hpp"
#include "sim/car.hpp"

namespace cardemo {

/// Closing speed of the car along `normal` (unit, from the car towards the surface), m/s, >= 0.
[[nodiscard]] double closingSpeed(const CarState& car, const Eigen::Vector2d& normal);

/// Removes the world velocity (forward speed plus slip) into a surface with unit `normal` (from the
/// car towards it), bouncing back `params.restitution` of it when faster than
/// `params.bounce_threshold`; the sliding along the surface loses at most
/// `params.contact_friction` times the normal change (Coulomb). The result goes back into the car's
/// frame as forward speed and lateral slip.
void removeClosingVelocity(CarState& car, const Eigen::Vector2d& normal, const CarParams& params);

/// Penetration (metres, > 0) that push-out leaves in place so that resting contact stays contact.
[[nodiscard]] double restingPenetration(const Eigen::Vector2d& position);

/// Excess penetration over the resting one (metres, > 0) too small to push out: the rounding of
/// a position near `position`.
[[nodiscard]] double pushOutSlack(const Eigen::Vector2d& position);

/// Shifts the car back inside `walls` when its bounds leave them, removing the velocity into each
/// wall it met; returns true when it moved, and then sets `normal` to the outward normal of the
/// wall it was pushed off furthest (x first on a tie).
bool keepInsideWalls(CarState& car, const CarParams& params, const Aabb2& walls,
                     Eigen::Vector2d& normal);

}  // namespace cardemo
