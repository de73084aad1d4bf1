#pragma once
/// Oriented box in 2D.

#include <Eigen/Core>
#include <array>

#include "geometry/aabb.hpp"

namespace cardemo {

/// Oriented rectangle: the set { center + a*axis + b*perp(axis) : |a| <= half.x, |b| <= half.y },
/// where perp(axis) = (-axis.y, axis.x). This exact definition is what the exact oracle uses too.
struct Obb2 {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< Centre, world metres.
  Eigen::Vector2d axis = Eigen::Vector2d::UnitX();   ///< Unit local +x (the heading), world frame.
  Eigen::Vector2d half = Eigen::Vector2d::Ones();    ///< Half extents along local x and y, metres.

  /// Box of a car: `length` along the heading, `width` across it, heading in degrees CCW from +x.
  [[nodiscard]] static Obb2 fromDegrees(const Eigen::Vector2d& center, double heading_deg,
                                        double length, double width);
  /// Local +y axis in the world frame.
  [[nodiscard]] Eigen::Vector2d perp() const { return {-axis.y(), axis.x()}; }
  /// Corners counter-clockwise, starting at local (+x, -y).
  [[nodiscard]] std::array<Eigen::Vector2d, 4> corners() const;
  /// Tight axis-aligned bounds.
  [[nodiscard]] Aabb2 aabb() const;
};

}  // namespace cardemo
