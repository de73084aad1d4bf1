#pragma once
/// Velocity and position response of the player's car against static surfaces.

#include <Eigen/Core>
#include <array>

#include "geometry/aabb.hpp"
#include "sim/car.hpp"
#include "sim/walls.hpp"

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

/// One wall's part in a step's response.
struct WallContact {
  bool touching = false;  ///< The car's box reaches the wall after the response.
  double closing = 0.0;   ///< Closing speed into the wall before the response, m/s (>= 0).
  double depth = 0.0;     ///< How far the box reaches past the wall's line after it, metres.
};

/// The walls' response of one step, in kWallSides order.
struct WallResponse {
  std::array<WallContact, kWallCount> walls;  ///< Per wall.
  bool moved = false;                         ///< The car was pushed back.
};

/// The walls a car's box touches (depth >= 0) without any response: their closing speeds and
/// depths (frame 0, where nothing moves).
[[nodiscard]] WallResponse touchedWalls(const CarState& car, const CarParams& params,
                                        const Aabb2& walls);

/// The walls' response, as a collider's: each wall the car's box touches (on each axis the west or
/// south one first) takes the velocity into it (bounce and friction as removeClosingVelocity,
/// both worked out from the velocity before the walls, so that a corner gives the same answer
/// whichever wall is "x"), and a box deeper than the resting penetration is pushed back to it, so
/// that a car held against a wall stays in contact.
[[nodiscard]] WallResponse respondToWalls(CarState& car, const CarParams& params,
                                          const Aabb2& walls);

}  // namespace cardemo
