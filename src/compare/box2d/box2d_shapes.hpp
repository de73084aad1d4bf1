#pragma once
/// Box2D 2.4.1 called the way its users call it: shapes in float, transforms in world coordinates.
///
/// This is the only place (with its .cpp) that includes Box2D; the core never sees it.

#include <box2d/b2_collision.h>
#include <box2d/b2_common.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include "geometry/convex_polygon.hpp"
#include "geometry/obb2.hpp"

namespace cardemo::compare {

/// Box2D's default polygon skin, metres (b2_polygonRadius = 2 * b2_linearSlop = 0.01 m).
inline constexpr float kBox2dDefaultSkin = b2_polygonRadius;

/// Box2D's answers for one pair.
struct Box2dVerdict {
  bool overlap = false;  ///< b2TestOverlap: GJK distance minus both skins < 10 * FLT_EPSILON.
  int points = 0;        ///< b2CollidePolygons: manifold point count (> 0 means contact).
};

/// A shape and its world transform, as a Box2D user would build them.
struct Box2dShape {
  b2PolygonShape shape;  ///< Polygon in its own frame (box) or in world coordinates (obstacle).
  b2Transform xf;        ///< World transform in float (identity for obstacles).
};

/// A box: SetAsBox(half extents) in its own frame, transform = float centre and b2Rot(float angle),
/// polygon skin `skin` metres (0 or kBox2dDefaultSkin).
[[nodiscard]] Box2dShape box2dBox(const Obb2& box, float skin);

/// Moves a box shape made by box2dBox to `box`'s pose (same extents), without rebuilding it.
void setBox2dPose(Box2dShape& shape, const Obb2& box);

/// A convex obstacle: b2PolygonShape::Set on its vertices in float world coordinates, identity
/// transform, skin `skin` metres. Box2D welds vertices closer than 0.0025 m (its own hull rule).
[[nodiscard]] Box2dShape box2dPolygon(const ConvexPolygon& polygon, float skin);

/// A two-sided edge (a wall of the scene's bounds), as a Box2D user builds a boundary.
struct Box2dEdge {
  b2EdgeShape shape;  ///< SetTwoSided on the float world end points; identity transform.
};

/// An edge from `a` to `b` (world metres, taken in float) with skin `skin` metres.
[[nodiscard]] Box2dEdge box2dEdge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, float skin);

/// Both of Box2D's verdicts for the pair (a, b).
[[nodiscard]] Box2dVerdict box2dCollide(const Box2dShape& a, const Box2dShape& b);

/// Both verdicts for a polygon against an edge: b2TestOverlap and b2CollideEdgeAndPolygon.
[[nodiscard]] Box2dVerdict box2dCollide(const Box2dShape& polygon, const Box2dEdge& edge);

}  // namespace cardemo::compare
