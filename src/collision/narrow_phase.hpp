#pragma once
/// Narrow-phase dispatch between the player's box and a static shape.

#include <variant>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "geometry/sat_result.hpp"
#include "geometry/sweep_result.hpp"

namespace cardemo {

/// A static collider: a parked car's box or a convex obstacle.
using StaticShape = std::variant<Obb2, ConvexPolygon>;

/// SAT between the player's box (A) and a static shape (B); normal from the player to the shape.
[[nodiscard]] SatResult2 collidePlayer(const Obb2& player, const StaticShape& shape);
/// SAT between the player's box (A) and a parked car's box (B); normal from the player to it.
[[nodiscard]] SatResult2 collidePlayer(const Obb2& player, const Obb2& box);
/// SAT between the player's box (A) and a convex obstacle (B); normal from the player to it.
[[nodiscard]] SatResult2 collidePlayer(const Obb2& player, const ConvexPolygon& polygon);

/// Swept SAT of the player's box (A) translating by `displacement` (world metres, t in [0, 1])
/// against a static shape (B); normal from the player to the shape.
[[nodiscard]] SweepResult2 sweepPlayer(const Obb2& player, const Eigen::Vector2d& displacement,
                                       const StaticShape& shape);
/// Swept SAT of the player's box against a parked car's box (as the StaticShape version).
[[nodiscard]] SweepResult2 sweepPlayer(const Obb2& player, const Eigen::Vector2d& displacement,
                                       const Obb2& box);
/// Swept SAT of the player's box against a convex obstacle (as the StaticShape version).
[[nodiscard]] SweepResult2 sweepPlayer(const Obb2& player, const Eigen::Vector2d& displacement,
                                       const ConvexPolygon& polygon);

/// Gap between the projections of the player's box and a static shape on the unit `axis` (pointing
/// from the player towards the shape), metres: > 0 apart along it, <= 0 overlapping by -gap.
[[nodiscard]] double separationAlong(const Obb2& player, const StaticShape& shape,
                                     const Eigen::Vector2d& axis);
/// Gap along `axis` between the player's box and a parked car's box (as the StaticShape version).
[[nodiscard]] double separationAlong(const Obb2& player, const Obb2& box,
                                     const Eigen::Vector2d& axis);
/// Gap along `axis` between the player's box and a convex obstacle (as the StaticShape version).
[[nodiscard]] double separationAlong(const Obb2& player, const ConvexPolygon& polygon,
                                     const Eigen::Vector2d& axis);

/// Tight bounds of a static shape.
[[nodiscard]] Aabb2 boundsOf(const StaticShape& shape);
/// Tight bounds of a parked car's box.
[[nodiscard]] Aabb2 boundsOf(const Obb2& box);
/// Tight bounds of a convex obstacle.
[[nodiscard]] Aabb2 boundsOf(const ConvexPolygon& polygon);

}  // namespace cardemo
