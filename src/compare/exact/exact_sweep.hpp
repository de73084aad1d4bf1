#pragma once
/// Exact oracle for the swept separating-axis queries (sweep_obb2, sweep_polygon), in GMP integers.
///
/// The inputs' double values are taken as exact (a box is exactly the set its Obb2 definition
/// describes, the displacement is exactly the given vector). The hit verdict over t in [0, 1] is
/// exact; the time of impact is the exact rational time rounded to the nearest double at the end.

#include <Eigen/Core>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"

namespace cardemo::exact {

/// Exact first contact of a translating box with a static shape.
struct ExactSweep {
  bool hit = false;  ///< Exact: the shapes share a point at some t in [0, 1].
  double toi = 1.0;  ///< Exact first contact time, rounded to double (when hit).
  Eigen::Vector2d normal =
      Eigen::Vector2d::UnitX();  ///< Unit contact normal from A to B (rounded).
  double closing = 0.0;  ///< |normal . displacement| at the entry axis, metres (0 when toi = 0).
};

/// Exact swept verdict of box `a` moving by `displacement` against the static box `b`. `inflate`
/// (metres, may be negative) widens A's projection on every candidate axis by that distance, for
/// telling borderline cases (the widening is exact to ~1e-70 m, not a rational identity).
[[nodiscard]] ExactSweep sweepObb2(const Obb2& a, const Eigen::Vector2d& displacement,
                                   const Obb2& b, double inflate = 0.0);

/// Exact swept verdict of box `a` moving by `displacement` against the static convex polygon `b`
/// (axes: the box's 2 axes and the polygon's exact edge normals); `inflate` as for sweepObb2.
[[nodiscard]] ExactSweep sweepObbPolygon(const Obb2& a, const Eigen::Vector2d& displacement,
                                         const ConvexPolygon& b, double inflate = 0.0);

}  // namespace cardemo::exact
