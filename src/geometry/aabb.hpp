#pragma once
/// Axis-aligned bounding boxes in 2D and 3D.

#include <Eigen/Core>

namespace cardemo {

/// Axis-aligned box in 2D, world metres; valid when min <= max component-wise.
struct Aabb2 {
  Eigen::Vector2d min = Eigen::Vector2d::Zero();  ///< Lower-left corner.
  Eigen::Vector2d max = Eigen::Vector2d::Zero();  ///< Upper-right corner.

  /// True when the boxes touch or overlap (closed intervals on both axes).
  [[nodiscard]] bool overlaps(const Aabb2& o) const {
    return min.x() <= o.max.x() && o.min.x() <= max.x() && min.y() <= o.max.y() &&
           o.min.y() <= max.y();
  }
  /// True when `o` lies entirely inside this box.
  [[nodiscard]] bool contains(const Aabb2& o) const {
    return min.x() <= o.min.x() && min.y() <= o.min.y() && o.max.x() <= max.x() &&
           o.max.y() <= max.y();
  }
  /// Smallest box enclosing this one and `o`.
  [[nodiscard]] Aabb2 merged(const Aabb2& o) const {
    return {min.cwiseMin(o.min), max.cwiseMax(o.max)};
  }
  /// Extent along x and y.
  [[nodiscard]] Eigen::Vector2d size() const { return max - min; }
  /// Bitwise equality (used to skip work when nothing moved).
  [[nodiscard]] bool operator==(const Aabb2& o) const = default;
};

/// Axis-aligned box in 3D, metres; valid when min <= max component-wise.
struct Aabb3 {
  Eigen::Vector3d min = Eigen::Vector3d::Zero();  ///< Lower corner.
  Eigen::Vector3d max = Eigen::Vector3d::Zero();  ///< Upper corner.

  /// True when the boxes touch or overlap (closed intervals on all three axes).
  [[nodiscard]] bool overlaps(const Aabb3& o) const {
    return (min.array() <= o.max.array()).all() && (o.min.array() <= max.array()).all();
  }
  /// True when `o` lies entirely inside this box.
  [[nodiscard]] bool contains(const Aabb3& o) const {
    return (min.array() <= o.min.array()).all() && (o.max.array() <= max.array()).all();
  }
  /// Smallest box enclosing this one and `o`.
  [[nodiscard]] Aabb3 merged(const Aabb3& o) const {
    return {min.cwiseMin(o.min), max.cwiseMax(o.max)};
  }
};

}  // namespace cardemo
