#include "collision/narrow_phase.hpp"

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

Aabb2 boundsOf(const StaticShape& shape) {
  return std::visit([](const auto& s) { return s.aabb(); }, shape);
}

}  // namespace cardemo
