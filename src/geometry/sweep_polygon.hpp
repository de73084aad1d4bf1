#pragma once
/// Swept separating-axis test: a 2D box translating against a static convex polygon.

#include <Eigen/Core>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "geometry/sweep_result.hpp"

namespace cardemo {

/// First contact of box `a` moving by `displacement` (world metres, over t in [0, 1]) with the
/// static convex polygon `b`: exact per-axis intervals on the box's 2 axes and the polygon's edge
/// normals. Coordinates are taken relative to A's centre first. Touching counts as contact; contact
/// at t = 0 gives toi = 0 with collideObbPolygon's normal and separation (bit for bit).
[[nodiscard]] SweepResult2 sweepObbPolygon(const Obb2& a, const Eigen::Vector2d& displacement,
                                           const ConvexPolygon& b);

}  // namespace cardemo
