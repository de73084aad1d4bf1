#include "collision/narrow_phase.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "geometry/sat_obb2.hpp"
#include "geometry/sweep_obb2.hpp"
#include "geometry/sweep_polygon.hpp"

namespace cardemo {

SatResult2 collidePlayer(const Obb2& player, const StaticShape& shape) {
  return std::visit(
      [&player](const auto& s) -> SatResult2 {
        if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Obb2>) {
          return collideObb2(player, s);
        } else {
          return collideObbPolygon(player, s);
        }
      },
      shape);
}

SweepResult2 sweepPlayer(const Obb2& player, const Eigen::Vector2d& displacement,
                         const StaticShape& shape) {
  return std::visit(
      [&](const auto& s) -> SweepResult2 {
        if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Obb2>) {
          return sweepObb2(player, displacement, s);
        } else {
          return sweepObbPolygon(player, displacement, s);
        }
      },
      shape);
}

namespace {

// Half the width of a box's projection on a unit axis.
double radiusAlong(const Obb2& box, const Eigen::Vector2d& axis) {
  const Eigen::Vector2d perp = box.perp();
  return std::abs(box.axis.x() * axis.x() + box.axis.y() * axis.y()) * box.half.x() +
         std::abs(perp.x() * axis.x() + perp.y() * axis.y()) * box.half.y();
}

}  // namespace

double separationAlong(const Obb2& player, const StaticShape& shape, const Eigen::Vector2d& axis) {
  const double player_max =
      player.center.x() * axis.x() + player.center.y() * axis.y() + radiusAlong(player, axis);
  const double shape_min = std::visit(
      [&axis](const auto& s) -> double {
        if constexpr (std::is_same_v<std::decay_t<decltype(s)>, Obb2>) {
          return s.center.x() * axis.x() + s.center.y() * axis.y() - radiusAlong(s, axis);
        } else {
          double lowest = s.vertex(0).x() * axis.x() + s.vertex(0).y() * axis.y();
          for (int i = 1; i < s.count; ++i) {
            lowest = std::min(lowest, s.vertex(i).x() * axis.x() + s.vertex(i).y() * axis.y());
          }
          return lowest;
        }
      },
      shape);
  return shape_min - player_max;
}

Aabb2 boundsOf(const StaticShape& shape) {
  return std::visit([](const auto& s) { return s.aabb(); }, shape);
}

}  // namespace cardemo
