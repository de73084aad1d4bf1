#pragma once
/// Convex polygons (obstacles) and their separating-axis tests.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>
#include <string>

#include "geometry/aabb.hpp"
#include "geometry/obb2.hpp"
#include "geometry/polygon_view.hpp"
#include "geometry/sat_result.hpp"

namespace cardemo {

/// Convex polygon with 3 to kMaxVertices vertices, stored counter-clockwise; fixed capacity so the
/// per-frame path never allocates.
struct ConvexPolygon {
  static constexpr int kMaxVertices = 16;                ///< Capacity (the scene format's limit).
  int count = 0;                                         ///< Number of vertices in use.
  std::array<Eigen::Vector2d, kMaxVertices> vertices{};  ///< First `count` are used, CCW.

  /// Builds a polygon from points in either winding. Returns nullopt and sets `why` when the points
  /// are fewer than 3, more than kMaxVertices, not finite, collinear/degenerate, repeated or not
  /// strictly convex.
  [[nodiscard]] static std::optional<ConvexPolygon> fromPoints(
      std::span<const Eigen::Vector2d> points, std::string* why = nullptr);
  /// The four corners of a box as a polygon.
  [[nodiscard]] static ConvexPolygon fromObb(const Obb2& box);
  /// Vertex i (0 <= i < count).
  [[nodiscard]] const Eigen::Vector2d& vertex(int i) const {
    return vertices[static_cast<std::size_t>(i)];
  }
  /// The polygon as a view (what the pair queries take); valid while this polygon is unchanged.
  [[nodiscard]] operator PolygonView() const { return {vertices.data(), count}; }
  /// Tight axis-aligned bounds.
  [[nodiscard]] Aabb2 aabb() const;
  /// Mean of the vertices (a point strictly inside).
  [[nodiscard]] Eigen::Vector2d centroid() const;
};

/// SAT over the edge normals of both polygons: separation and unit normal from A towards B
/// (src/geometry/sat_polygon.cpp).
/// Accurate far from the origin (coordinates are taken relative to A's first vertex first).
[[nodiscard]] SatResult2 collidePolygons(PolygonView a, PolygonView b);

/// SAT between a polygon and a box (box axes + polygon edge normals); normal from A (polygon) to B.
[[nodiscard]] SatResult2 collidePolygonObb(PolygonView a, const Obb2& b);

/// SAT between a box and a polygon; normal from A (box) to B (polygon).
[[nodiscard]] SatResult2 collideObbPolygon(const Obb2& a, PolygonView b);

}  // namespace cardemo
