#pragma once
/// Seeded random swept-query cases (a moving box, a static box or polygon) for the property tests.

#include <Eigen/Core>
#include <numbers>
#include <type_traits>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "random_cases2.hpp"

namespace cardemo::testing {

/// Accuracy band of the swept queries, metres: the verdict must match the exact one unless the
/// shapes come within this distance of touching (or of separating) over the sweep, and the time of
/// impact must be right to this distance along the contact normal.
inline constexpr double kSweepTolerance = 1e-6;

/// One swept case: box A moves by `d`; B is static.
struct SweepCase {
  Obb2 a;             ///< Moving box at t = 0.
  Eigen::Vector2d d;  ///< Displacement over the sweep, metres.
};

/// A moving box near `target` (a point of B) with sides in [1 cm, 100 m], aimed at about it: the
/// start is 0.5 to 8 combined radii away in a random direction, the displacement reaches from 0 to
/// 2.5 times that distance, aimed within +-0.6 rad of the target (so about half the cases hit).
inline SweepCase sweepCase(Random& rng, const Eigen::Vector2d& target, double target_radius) {
  SweepCase c;
  c.a = rng.extremeBox(Eigen::Vector2d::Zero());
  const double reach = c.a.half.norm() + target_radius;
  const Eigen::Vector2d direction = rng.direction();
  const Eigen::Vector2d away = direction * reach * rng.uniform(0.5, 8.0);
  c.a.center = target + away;
  const double angle = rng.uniform(-0.6, 0.6);
  const Eigen::Vector2d towards = -away.normalized();
  const Eigen::Vector2d aim{towards.x() * std::cos(angle) - towards.y() * std::sin(angle),
                            towards.x() * std::sin(angle) + towards.y() * std::cos(angle)};
  c.d = aim * away.norm() * rng.uniform(0.0, 2.5);
  return c;
}

/// Radius of the circle around a polygon's centroid that holds it.
inline double polygonReach(const ConvexPolygon& p) {
  const Eigen::Vector2d c = p.centroid();
  double r = 0.0;
  for (int i = 0; i < p.count; ++i) r = std::max(r, (p.vertex(i) - c).norm());
  return r;
}

/// A static shape up to 1e7 m from the origin (an extreme box, or a polygon of 1 cm to 100 m) and a
/// moving box aimed at it (sweepCase).
template <class Shape>
struct SweepTarget {
  Shape b;      ///< The static shape.
  SweepCase c;  ///< The moving box and its displacement.
};

/// Draws one SweepTarget: the shape, then the moving box aimed at its centre or centroid.
template <class Shape>
SweepTarget<Shape> sweepTarget(Random& rng) {
  const Eigen::Vector2d centre = rng.farPoint(1e7);
  SweepTarget<Shape> t;
  Eigen::Vector2d target = centre;
  double reach = 0.0;
  if constexpr (std::is_same_v<Shape, Obb2>) {
    t.b = rng.extremeBox(centre);
    reach = t.b.half.norm();
  } else {
    t.b = rng.polygon(centre, 0.01, 100.0);
    target = t.b.centroid();
    reach = polygonReach(t.b);
  }
  t.c = sweepCase(rng, target, reach);
  return t;
}

}  // namespace cardemo::testing
