#pragma once
/// Convex polygons packed end to end, for scenes and batches of many polygons.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/polygon_view.hpp"

namespace cardemo {

/// Polygons stored back to back: 16 bytes per vertex and 4 per polygon, so a quadrilateral takes
/// 68 bytes where a ConvexPolygon (room for kMaxVertices) takes 272. Views stay valid until the
/// next add().
class PolygonStore {
 public:
  /// Appends a copy of `polygon` (3 to ConvexPolygon::kMaxVertices vertices) and returns its index.
  std::size_t add(PolygonView polygon);
  /// Reserves room for `polygons` polygons of `vertices` vertices in all.
  void reserve(std::size_t polygons, std::size_t vertices);
  /// Number of polygons.
  [[nodiscard]] std::size_t size() const { return starts_.size() - 1; }
  /// Polygon i (i < size()).
  [[nodiscard]] PolygonView operator[](std::size_t i) const {
    const std::uint32_t first = starts_[i];
    return {vertices_.data() + first, static_cast<int>(starts_[i + 1] - first)};
  }

 private:
  std::vector<Eigen::Vector2d> vertices_;
  std::vector<std::uint32_t> starts_{0};  // polygon i is vertices_[starts_[i], starts_[i + 1])
};

}  // namespace cardemo
