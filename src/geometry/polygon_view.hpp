#pragma once
/// A read-only convex polygon whose vertices are stored elsewhere.

#include <Eigen/Core>
#include <cstddef>

namespace cardemo {

/// `count` counter-clockwise vertices in contiguous memory owned by a ConvexPolygon or a
/// PolygonStore; cheap to copy, valid while the owner is unchanged (as std::string_view).
struct PolygonView {
  const Eigen::Vector2d* vertices = nullptr;  ///< The first of `count` vertices.
  int count = 0;                              ///< Number of vertices.

  /// Vertex i (0 <= i < count).
  [[nodiscard]] const Eigen::Vector2d& vertex(int i) const {
    return vertices[static_cast<std::size_t>(i)];
  }
};

}  // namespace cardemo
