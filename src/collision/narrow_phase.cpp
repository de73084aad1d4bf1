#include "collision/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/sat_obb2.hpp"
#include "geometry/sweep_obb2.hpp"
#include "geometry/sweep_polygon.hpp"

namespace cardemo {

SatResult2 collidePlayer(const Obb2& player, const Obb2& box) {
  return collideObb2(player, box);
}

SatResult2 collidePlayer(const Obb2& player, const ConvexPolygon& polygon) {
  return collideObbPolygon(player, polygon);
}

SatResult2 collidePlayer(const Obb2& player, const StaticShape& shape) {
  return std::visit([&player](const auto& s) { return collidePlayer(player, s); }, shape);
}

SweepResult2 sweepPlayer(const Obb2& player, const Eigen::Vector2d& displacement, const Obb2& box) {
  return sweepObb2(player, displacement, box);
}

SweepResult2 sweepPlayer(const Obb2& player, const Eigen::Vector2d& displacement,
                         const ConvexPolygon& polygon) {
  return sweepObbPolygon(player, displacement, polygon);
}

SweepResult2 sweepPlayer(const Obb2& player, const Eigen::Vector2d& displacement,
                         const StaticShape& shape) {
  return std::visit([&](const auto& s) { return sweepPlayer(player, displacement, s); }, shape);
}

namespace {

// Half the width of a box's projection on a unit axis.
double radiusAlong(const Obb2& box, const Eigen::Vector2d& axis) {
  const Eigen::Vector2d perp = box.perp();
  return std::abs(box.axis.x() * axis.x() + box.axis.y() * axis.y()) * box.half.x() +
         std::abs(perp.x() * axis.x() + perp.y() * axis.y()) * box.half.y();
}

// The far end of the player's box along the axis, where the gap to a shape starts.
double playerMaxAlong(const Obb2& player, const Eigen::Vector2d& axis) {
  return player.center.x() * axis.x() + player.center.y() * axis.y() + radiusAlong(player, axis);
}

}  // namespace

double separationAlong(const Obb2& player, const Obb2& box, const Eigen::Vector2d& axis) {
  const double player_max = playerMaxAlong(player, axis);
  const double box_min =
      box.center.x() * axis.x() + box.center.y() * axis.y() - radiusAlong(box, axis);
  return box_min - player_max;
}

double separationAlong(const Obb2& player, const ConvexPolygon& polygon,
                       const Eigen::Vector2d& axis) {
  const double player_max = playerMaxAlong(player, axis);
  double lowest = polygon.vertex(0).x() * axis.x() + polygon.vertex(0).y() * axis.y();
  for (int i = 1; i < polygon.count; ++i) {
    lowest = std::min(lowest, polygon.vertex(i).x() * axis.x() + polygon.vertex(i).y() * axis.y());
  }
  return lowest - player_max;
}

double separationAlong(const Obb2& player, const StaticShape& shape, const Eigen::Vector2d& axis) {
  return std::visit([&](const auto& s) { return separationAlong(player, s, axis); }, shape);
}

Aabb2 boundsOf(const Obb2& box) {
  return box.aabb();
}

Aabb2 boundsOf(const ConvexPolygon& polygon) {
  return polygon.aabb();
}

Aabb2 boundsOf(const StaticShape& shape) {
  return std::visit([](const auto& s) { return boundsOf(s); }, shape);
}

}  // namespace cardemo
