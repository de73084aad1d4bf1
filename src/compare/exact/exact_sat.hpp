#pragma once
/// Exact oracle for the separating-axis queries, in GMP rationals.
///
/// The inputs' double values are taken as exact rationals (a box is exactly the set its Obb2/Obb3/
/// ConvexPolygon definition describes). The hit verdict is exact. The separation is each axis's
/// exact rational gap divided by the axis length, evaluated with 256-bit floats, so it is correct
/// to far below a nanometre.

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"
#include "geometry/obb3.hpp"
#include "sim/walls.hpp"

namespace cardemo::exact {

/// Exact verdict for one pair.
struct ExactResult {
  bool hit = false;         ///< Exact: the closed shapes share at least one point.
  double separation = 0.0;  ///< Max over candidate axes of the gap, rounded to double at the end.
};

/// Exact SAT verdict for two 2D boxes (axes: the 4 edge normals).
[[nodiscard]] ExactResult collideObb2(const Obb2& a, const Obb2& b);

/// Exact SAT verdict for two convex polygons (axes: every edge normal of both).
[[nodiscard]] ExactResult collidePolygons(const ConvexPolygon& a, const ConvexPolygon& b);

/// Exact SAT verdict for a box and a convex polygon (axes: the box's 2 axes, taken exactly as
/// stored, and every polygon edge normal). Unlike collidePolygons(ConvexPolygon::fromObb(box), p),
/// the box is not rounded to double corners first: a 1 cm box far from the origin would get edge
/// directions off by ~1e-7 rad, which is 2e-5 m over a 200 m gap.
[[nodiscard]] ExactResult collideObbPolygon(const Obb2& box, const ConvexPolygon& polygon);

/// Exact verdict for a box against one wall of `walls` (the half-plane beyond that edge of the
/// bounds): the gap from the box's furthest corner to the wall's line, which the box touches when
/// the gap is <= 0.
[[nodiscard]] ExactResult collideObbWall(const Obb2& box, const Aabb2& walls, WallSide side);

/// Exact SAT verdict for two 3D boxes: 6 face normals (cross products of the stored edge columns)
/// and the 9 edge-edge cross products, skipping exactly-zero ones (exact, see obb3.hpp).
[[nodiscard]] ExactResult collideObb3(const Obb3& a, const Obb3& b);

}  // namespace cardemo::exact
